#include "plugins/activity/RawWindows.h"

#include <QFile>
#include <QStringList>
#include <algorithm>
#include <cstring>

namespace athlos::activity {

void rawWindow(const StreamData& data, const std::vector<int>& columns, double tStart, double tEnd, int length,
               float* out) {
    const std::size_t n = data.rows();
    const auto c = std::size_t(data.columns);
    if (n == 0 || length < 1) {
        std::fill(out, out + columns.size() * std::size_t(std::max(length, 0)), 0.0f);
        return;
    }
    const double dt = length > 1 ? (tEnd - tStart) / double(length - 1) : 0.0;
    // data.t[k] <= t < data.t[k + 1] (times only grow along the window); found by bisection, not by a scan
    // from the stream's start, which made cutting all windows of a stream quadratic in its length.
    std::size_t k = std::size_t(std::upper_bound(data.t.begin(), data.t.end(), tStart) - data.t.begin());
    k = k > 0 ? k - 1 : 0;
    for (int j = 0; j < length; ++j) {
        const double t = tStart + dt * double(j);
        while (k + 1 < n && data.t[k + 1] <= t) ++k;
        std::size_t a = k, b = std::min(k + 1, n - 1);
        double w = 0.0;  // weight of b
        if (t <= data.t.front()) {
            a = b = 0;
        } else if (t >= data.t.back()) {
            a = b = n - 1;
        } else if (data.t[b] > data.t[a]) {
            w = (t - data.t[a]) / (data.t[b] - data.t[a]);
        }
        for (std::size_t ch = 0; ch < columns.size(); ++ch) {
            const auto col = std::size_t(columns[ch]);
            const double va = data.values[a * c + col], vb = data.values[b * c + col];
            out[ch * std::size_t(length) + std::size_t(j)] = float(va + w * (vb - va));
        }
    }
}

namespace {
Status writeNpyRaw(const QString& path, const std::vector<long long>& shape, const char* descr, const void* values,
                   std::size_t bytes) {
    QStringList dims;
    for (long long d : shape) dims << QString::number(d);
    QString shapeText = dims.join(QStringLiteral(", "));
    if (shape.size() == 1) shapeText += QLatin1Char(',');
    QByteArray header = QStringLiteral("{'descr': '%1', 'fortran_order': False, 'shape': (%2), }")
                            .arg(QLatin1String(descr), shapeText)
                            .toLatin1();
    // Magic (6) + version (2) + header length (2) + header, padded with spaces to a multiple of 64, '\n' last.
    const qsizetype total = ((10 + header.size() + 1 + 63) / 64) * 64;
    header.append(QByteArray(total - 10 - header.size() - 1, ' '));
    header.append('\n');
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly | QIODevice::Truncate))
        return makeError(QStringLiteral("%1: cannot write (%2)").arg(path, f.errorString()));
    QByteArray prefix("\x93NUMPY\x01\x00", 8);
    const auto len = quint16(header.size());
    prefix.append(char(len & 0xff));
    prefix.append(char(len >> 8));
    if (f.write(prefix) != prefix.size() || f.write(header) != header.size() ||
        f.write(static_cast<const char*>(values), qint64(bytes)) != qint64(bytes))
        return makeError(QStringLiteral("%1: cannot write (%2)").arg(path, f.errorString()));
    return {};
}

std::size_t count(const std::vector<long long>& shape) {
    std::size_t n = 1;
    for (long long d : shape) n *= std::size_t(std::max(d, 0LL));
    return n;
}
}  // namespace

// x86-64 and aarch64 are little-endian, which '<f4' / '<i4' declare.
Status writeNpy(const QString& path, const std::vector<long long>& shape, const float* values) {
    return writeNpyRaw(path, shape, "<f4", values, count(shape) * sizeof(float));
}

Status writeNpy(const QString& path, const std::vector<long long>& shape, const int* values) {
    return writeNpyRaw(path, shape, "<i4", values, count(shape) * sizeof(int));
}

}  // namespace athlos::activity
