#include "core/model/StreamData.h"

#include "core/math/Statistics.h"

#include <openssl/evp.h>

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
    return math::upperMedian(std::move(dt));
}

QByteArray StreamData::contentHash() const {
    // SHA-256 through OpenSSL's EVP: the same digest as QCryptographicHash, but it uses the CPU's
    // SHA extensions (~10x faster), which matters because every import and result is hashed.
    static_assert(sizeof(double) == 8);
    EVP_MD_CTX* ctx = EVP_MD_CTX_new();
    EVP_DigestInit_ex(ctx, EVP_sha256(), nullptr);
    const qint64 header[2] = {static_cast<qint64>(t.size()), columns};
    EVP_DigestUpdate(ctx, header, sizeof(header));
    EVP_DigestUpdate(ctx, t.data(), t.size() * sizeof(double));
    EVP_DigestUpdate(ctx, values.data(), values.size() * sizeof(double));
    unsigned char digest[EVP_MAX_MD_SIZE];
    unsigned int length = 0;
    EVP_DigestFinal_ex(ctx, digest, &length);
    EVP_MD_CTX_free(ctx);
    return QByteArray(reinterpret_cast<const char*>(digest), int(length)).toHex();
}

}  // namespace athlos
