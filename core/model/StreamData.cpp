#include "core/model/StreamData.h"

#include <QCryptographicHash>
#include <algorithm>

namespace athlos {

long long StreamData::firstNonIncreasing() const {
    for (std::size_t i = 1; i < t.size(); ++i) {
        // Written as !(a > b) so that NaN time stamps are caught too.
        if (!(t[i] > t[i - 1])) return static_cast<long long>(i);
    }
    return -1;
}

double StreamData::medianInterval() const {
    if (t.size() < 2) return 0.0;
    std::vector<double> dt(t.size() - 1);
    for (std::size_t i = 1; i < t.size(); ++i) dt[i - 1] = t[i] - t[i - 1];
    auto mid = dt.begin() + static_cast<long>(dt.size() / 2);
    std::nth_element(dt.begin(), mid, dt.end());
    return *mid;
}

QByteArray StreamData::contentHash() const {
    static_assert(sizeof(double) == 8);
    QCryptographicHash hash(QCryptographicHash::Sha256);
    const qint64 header[2] = {static_cast<qint64>(t.size()), columns};
    hash.addData(QByteArrayView(reinterpret_cast<const char*>(header), sizeof(header)));
    hash.addData(QByteArrayView(reinterpret_cast<const char*>(t.data()), qsizetype(t.size() * sizeof(double))));
    hash.addData(QByteArrayView(reinterpret_cast<const char*>(values.data()),
                                qsizetype(values.size() * sizeof(double))));
    return hash.result().toHex();
}

}  // namespace athlos
