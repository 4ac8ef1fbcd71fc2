#include "ui/ClockTimeTicker.h"

#include "core/io/TimeFormats.h"

namespace athlos::ui {

ClockTimeTicker::ClockTimeTicker(double t0) : t0_(t0) {
    setDateTimeSpec(Qt::UTC);
    setDateTimeFormat(QStringLiteral("HH:mm:ss"));
}

std::optional<double> ClockTimeTicker::t0Of(const QJsonObject& attributes) {
    if (const QString utc = attributes.value(QStringLiteral("t0_utc")).toString(); !utc.isEmpty()) {
        if (const auto ns = parseUtc(utc)) return double(*ns) * 1e-9;
        return std::nullopt;
    }
    const QString timeOfDay = attributes.value(QStringLiteral("t0_time_of_day")).toString();
    qint64 ns = 0;
    if (!timeOfDay.isEmpty() && parseClockTime(timeOfDay.toStdString(), ns)) return double(ns) * 1e-9;
    return std::nullopt;
}

QString ClockTimeTicker::getTickLabel(double tick, const QLocale& locale, QChar formatChar, int precision) {
    // Milliseconds once ticks are less than a second apart, the date once they are days apart.
    setDateTimeFormat(step_ < 1.0        ? QStringLiteral("HH:mm:ss.zzz")
                      : step_ >= 86400.0 ? QStringLiteral("yyyy-MM-dd")
                                         : QStringLiteral("HH:mm:ss"));
    return QCPAxisTickerDateTime::getTickLabel(tick + t0_, locale, formatChar, precision);
}

QVector<double> ClockTimeTicker::createTickVector(double tickStep, const QCPRange& range) {
    step_ = tickStep;
    // Round clock times: the base class places ticks on the absolute range, then back to t.
    QVector<double> ticks =
        QCPAxisTickerDateTime::createTickVector(tickStep, QCPRange(range.lower + t0_, range.upper + t0_));
    for (double& tick : ticks) tick -= t0_;
    return ticks;
}

}  // namespace athlos::ui
