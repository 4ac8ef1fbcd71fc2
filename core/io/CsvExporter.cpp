// CSV export in the interchange convention, so that export → import gives back the same values
// bit for bit: numbers in std::to_chars' shortest round-trip form, NaN as an empty cell, `t` first.
// A column's unit goes into the header ("name [unit]") only where the kind does not imply it, so
// files of known kinds have plain names and still re-import with the same units.
// The CSV side of core/io/Exporter.h; the HDF5 exporters live elsewhere.
#include "core/io/Exporter.h"
#include "core/io/TdoaLayout.h"
#include "core/model/StreamKinds.h"

#include <QFileInfo>
#include <QSaveFile>
#include <charconv>
#include <cmath>
#include <string>

namespace athlos {
namespace {

constexpr size_t kFlushBytes = 1 << 20;

void appendNumber(std::string& out, double v) {
    if (std::isnan(v)) return;  // empty cell
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    out.append(buf, r.ptr);
}

// Quotes what the reader would otherwise split, trim or skip.
void appendText(std::string& out, const QString& text, bool firstCell) {
    const QByteArray utf8 = text.toUtf8();
    const bool quote = utf8.isEmpty() || utf8.contains(',') || utf8.contains(';') || utf8.contains('\t') ||
                       utf8.contains('"') || utf8.contains('\n') || utf8.contains('\r') || utf8.front() == ' ' ||
                       utf8.back() == ' ' || (firstCell && utf8.front() == '#');
    if (!quote) {
        out.append(utf8.constData(), size_t(utf8.size()));
        return;
    }
    out.push_back('"');
    for (char c : utf8) {
        if (c == '"') out.push_back('"');
        out.push_back(c);
    }
    out.push_back('"');
}

QString headerCell(const QString& name, const QString& unit, const StreamKind* kind) {
    const QString implied = kind ? kind->unitFor(name) : QString();
    // A column whose kind assumes another unit when none is written (barometer pressure: hPa) keeps
    // its unit in the header, so that a re-import reads it back unchanged.
    const bool assumed = kind && !kind->assumedUnitFor(name).isEmpty();
    if (!unit.isEmpty() && (unit != implied || assumed)) return QStringLiteral("%1 [%2]").arg(name, unit);
    if (name.endsWith(QLatin1Char(')')) || name.endsWith(QLatin1Char(']')))
        return name + QStringLiteral(" []");  // so that the end of the name is not read as a unit
    return name;
}

class CsvFile {
public:
    explicit CsvFile(const QString& file) : out_(file) {}
    Status open() {
        if (!out_.open(QIODevice::WriteOnly))
            return makeError(QStringLiteral("%1: cannot write: %2").arg(out_.fileName(), out_.errorString()));
        buffer_.reserve(kFlushBytes + 4096);
        return {};
    }
    std::string& buffer() { return buffer_; }
    // Writes the buffer once it is large; returns false on a write error.
    bool flush(bool force = false) {
        if (!force && buffer_.size() < kFlushBytes) return true;
        const bool ok = out_.write(buffer_.data(), qint64(buffer_.size())) == qint64(buffer_.size());
        buffer_.clear();
        return ok;
    }
    Status commit() {
        if (!flush(true) || !out_.commit())
            return makeError(QStringLiteral("%1: cannot write: %2").arg(out_.fileName(), out_.errorString()));
        return {};
    }
    void cancel() { out_.cancelWriting(); }
    Error writeError() {
        out_.cancelWriting();
        return makeError(QStringLiteral("%1: cannot write: %2").arg(out_.fileName(), out_.errorString()));
    }

private:
    QSaveFile out_;
    std::string buffer_;
};

}  // namespace

Status exportStreamCsv(const Stream& stream, const QString& file, const Progress& progress) {
    const auto loaded = stream.data();
    if (!loaded) return makeError(QStringLiteral("%1: cannot load samples: %2").arg(stream.name(), loaded.message()));
    const StreamData& data = **loaded;
    const StreamInfo& info = stream.info();
    if (int(info.columns.size()) != data.columns)
        return makeError(QStringLiteral("%1: %2 column names for %3 columns")
                             .arg(stream.name())
                             .arg(info.columns.size())
                             .arg(data.columns));
    const StreamKind* kind = findStreamKind(info.kind);

    CsvFile out(file);
    if (Status s = out.open(); !s) return s;
    std::string& buf = out.buffer();
    if (const LongLayout* layout = longLayoutOf(info.kind)) {
        // Back to the long interchange form (TdoaLayout.h); cells that were not received are skipped.
        buf += "t,beacon," + layout->value.toStdString() + '\n';
        bool ok = true;
        forEachLongSample(*layout, info, data, [&](double t, const QString& beacon, double dt) {
            appendNumber(buf, t);
            buf += ',';
            appendText(buf, beacon, false);
            buf += ',';
            appendNumber(buf, dt);
            buf += '\n';
            ok = ok && out.flush();
        });
        if (!ok) return out.writeError();
        return out.commit();
    }
    buf += 't';
    for (const Column& col : info.columns) {
        buf += ',';
        appendText(buf, headerCell(col.name, col.unit, kind), false);
    }
    buf += '\n';
    const size_t rows = data.rows();
    for (size_t r = 0; r < rows; ++r) {
        appendNumber(buf, data.t[r]);
        for (int c = 0; c < data.columns; ++c) {
            buf += ',';
            appendNumber(buf, data.at(r, c));
        }
        buf += '\n';
        if (buf.size() >= kFlushBytes) {
            if (progress.isCancelled()) {
                out.cancel();
                return makeError(QStringLiteral("cancelled"));
            }
            if (!out.flush()) return out.writeError();
            progress.report(double(r) / double(rows), QStringLiteral("Writing %1").arg(QFileInfo(file).fileName()));
        }
    }
    progress.report(1.0);
    return out.commit();
}

Status exportTableCsv(const Table& table, const QString& file) {
    const long long rows = table.rows();
    for (const TableColumn& col : table.columns)
        if (col.size() != rows)
            return makeError(QStringLiteral("%1: column '%2' has %3 rows, the first column %4")
                                 .arg(table.name, col.name)
                                 .arg(col.size())
                                 .arg(rows));
    const StreamKind* kind = findStreamKind(table.kind);
    CsvFile out(file);
    if (Status s = out.open(); !s) return s;
    std::string& buf = out.buffer();
    for (size_t c = 0; c < table.columns.size(); ++c) {
        if (c > 0) buf += ',';
        const TableColumn& col = table.columns[c];
        appendText(buf, headerCell(col.name, col.unit, kind), c == 0);
    }
    buf += '\n';
    for (long long r = 0; r < rows; ++r) {
        for (size_t c = 0; c < table.columns.size(); ++c) {
            if (c > 0) buf += ',';
            const TableColumn& col = table.columns[c];
            if (col.isText)
                appendText(buf, col.texts.at(qsizetype(r)), c == 0);
            else if (table.columns.size() == 1 && std::isnan(col.numbers[size_t(r)]))
                buf += "nan";  // an empty cell would make a blank line, which readers skip
            else
                appendNumber(buf, col.numbers[size_t(r)]);
        }
        buf += '\n';
        if (!out.flush()) return out.writeError();
    }
    return out.commit();
}

}  // namespace athlos
