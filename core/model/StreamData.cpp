#include "core/model/StreamData.h"

#include "core/math/Statistics.h"

#include <openssl/crypto.h>
#include <openssl/evp.h>

namespace athlos {

namespace {

// OpenSSL initialises itself on first use and registers its exit handler then; that handler deletes
// the thread-local keys, so a thread that used OpenSSL and exits *after* it (e.g. a thread of Qt's
// global pool, joined when the pool is destroyed at exit) loses its 904-byte error state, a leak
// LeakSanitizer reports (CI stop 22, `athlos report`). Initialising when this library is loaded
// registers the handler before any pool exists, so it runs after the pools have joined their
// threads. Regression test: tests/exit/HashInThreadAtExit.cpp.
[[maybe_unused]] const bool openSslInitialisedAtLoad = OPENSSL_init_crypto(OPENSSL_INIT_LOAD_CONFIG, nullptr) == 1;

}  // namespace

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
