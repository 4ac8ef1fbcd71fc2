#pragma once
// Import options carried by the input itself: a first line such as
//   # fuzz: kind=beacons; repair=sort; time-column=Time; time-unit=ms; map=Gyro X>gyr_x:deg/s; skip=Date
// CSV readers skip lines starting with '#', so the rest of the file is read as usual, and the
// fuzzer mutates the options along with the data.
#include "core/io/Importer.h"

#include <QByteArray>
#include <QList>
#include <QString>

namespace athlos::fuzz {

inline ImportOptions optionsFromInput(const QByteArray& input) {
    ImportOptions options;
    options.target = QStringLiteral("rec");
    if (!input.startsWith("# fuzz:")) return options;
    const qsizetype eol = input.indexOf('\n');
    const QString line = QString::fromUtf8(input.mid(7, eol < 0 ? -1 : eol - 7)).trimmed();
    for (const QString& item : line.split(QLatin1Char(';'), Qt::SkipEmptyParts)) {
        const QString key = item.section(QLatin1Char('='), 0, 0).trimmed();
        const QString value = item.section(QLatin1Char('='), 1).trimmed();
        if (key == u"kind")
            options.kind = value;
        else if (key == u"repair")
            options.timeRepair = value;
        else if (key == u"frame")
            options.frame = value;
        else if (key == u"time-column")
            options.timeColumn = value;
        else if (key == u"time-unit")
            options.timeUnit = value;
        else if (key == u"skip")
            options.columns.push_back({value, {}, {}, true});
        else if (key == u"map") {  // source>channel:unit
            ColumnMapping m;
            m.source = value.section(QLatin1Char('>'), 0, 0);
            const QString to = value.section(QLatin1Char('>'), 1);
            m.channel = to.section(QLatin1Char(':'), 0, 0);
            m.unit = to.section(QLatin1Char(':'), 1);
            options.columns.push_back(m);
        }
    }
    return options;
}

}  // namespace athlos::fuzz
