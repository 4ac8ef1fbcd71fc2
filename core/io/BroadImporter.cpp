#include "core/io/BroadImporter.h"

#include "core/store/Hdf5Util.h"
#include "core/store/VerifiedFiles.h"
#include "core/util/IsolatedRun.h"

#include <cmath>
#include <cstring>

namespace athlos {
namespace {

constexpr char kSignature[] = "\x89HDF\r\n\x1a\n";

using h5::Handle;

bool hasSignature(const QByteArray& head) {
    // The superblock sits at 0, or after a user block at 512, 1024, 2048, ...
    for (qsizetype at = 0; at + 8 <= head.size(); at = at == 0 ? 512 : at * 2)
        if (std::memcmp(head.constData() + at, kSignature, 8) == 0) return true;
    return false;
}

bool hasDataset(hid_t file, const char* name) { return H5Lexists(file, name, H5P_DEFAULT) > 0; }

class BroadFile {
public:
    explicit BroadFile(QString path) : path_(std::move(path)) {}

    Status open() {
        if (H5Fis_hdf5(path_.toLocal8Bit().constData()) <= 0)
            return makeError(QStringLiteral("%1: not an HDF5 file").arg(path_));
        file_ = Handle(H5Fopen(path_.toLocal8Bit().constData(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
        if (!file_.valid())
            return makeError(QStringLiteral("%1: cannot open the HDF5 file (damaged or truncated?)").arg(path_));
        return {};
    }

    // A N×columns float dataset (columns 1 also accepts rank 1), row-major; integers and enums
    // (h5py stores bool as an int8 enum) are converted to 0/1 doubles.
    Expected<std::vector<double>> matrix(const char* name, int columns, hsize_t& rows) const {
        if (!hasDataset(file_, name))
            return makeError(
                QStringLiteral("%1: dataset '%2' is missing (not a BROAD file?)").arg(path_, QLatin1String(name)));
        Handle ds(H5Dopen2(file_, name, H5P_DEFAULT), H5Dclose);
        if (!ds.valid())
            return makeError(
                QStringLiteral("%1: cannot open dataset '%2' (damaged file?)").arg(path_, QLatin1String(name)));
        Handle space(H5Dget_space(ds), H5Sclose);
        hsize_t dims[2] = {0, 0};
        const int rank = space.valid() ? H5Sget_simple_extent_ndims(space) : -1;
        if (rank < 1 || rank > 2 || H5Sget_simple_extent_dims(space, dims, nullptr) < 0 ||
            (rank == 2 && dims[1] != hsize_t(columns)) || (rank == 1 && columns != 1))
            return makeError(
                QStringLiteral("%1: dataset '%2' should be N×%3").arg(path_, QLatin1String(name)).arg(columns));
        rows = dims[0];
        // A damaged extent must not become a huge allocation: the file (deflate at most ~1032:1)
        // cannot hold more than this.
        hsize_t fileSize = 0;
        H5Fget_filesize(file_, &fileSize);
        if (static_cast<long double>(rows) * columns * 8.0L > static_cast<long double>(fileSize) * 1100.0L + 4096.0L)
            return makeError(
                QStringLiteral("%1: dataset '%2' claims %3 rows, more than the file can hold (damaged file?)")
                    .arg(path_, QLatin1String(name))
                    .arg(rows));
        std::vector<double> out(rows * hsize_t(columns));
        Handle type(H5Dget_type(ds), H5Tclose);
        herr_t status = -1;
        if (type.valid() && H5Tget_class(type) == H5T_ENUM) {
            // HDF5 has no enum→double conversion: read the enum in native byte order, decode its base.
            Handle native(H5Tget_native_type(type, H5T_DIR_ASCEND), H5Tclose);
            Handle base(native.valid() ? H5Tget_super(native) : -1, H5Tclose);
            const size_t size = base.valid() ? H5Tget_size(base) : 0;
            if (size == 0 || size > 8)
                return makeError(
                    QStringLiteral("%1: dataset '%2' has an unsupported type").arg(path_, QLatin1String(name)));
            std::vector<unsigned char> raw(out.size() * size);
            status = H5Dread(ds, native, H5S_ALL, H5S_ALL, H5P_DEFAULT, raw.data());
            const bool isSigned = H5Tget_sign(base) == H5T_SGN_2;
            for (size_t i = 0; i < out.size(); ++i) {
                long long v = 0;
                std::memcpy(&v, raw.data() + i * size, size);  // little-endian host
                if (isSigned && size < 8 && (v >> (size * 8 - 1)) & 1) v -= 1LL << (size * 8);
                out[i] = double(v);
            }
        } else {
            status = H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data());
        }
        if (status < 0)
            return makeError(QStringLiteral("%1: cannot read dataset '%2' (damaged or truncated file?)")
                                 .arg(path_, QLatin1String(name)));
        return out;
    }

    Expected<double> samplingRate() const {
        if (H5Aexists(file_, "sampling_rate") <= 0)
            return makeError(
                QStringLiteral("%1: root attribute 'sampling_rate' is missing (not a BROAD file?)").arg(path_));
        Handle attr(H5Aopen(file_, "sampling_rate", H5P_DEFAULT), H5Aclose);
        double rate = 0.0;
        if (!attr.valid() || H5Aread(attr, H5T_NATIVE_DOUBLE, &rate) < 0)
            return makeError(QStringLiteral("%1: cannot read attribute 'sampling_rate'").arg(path_));
        if (!std::isfinite(rate) || rate <= 0.0)
            return makeError(QStringLiteral("%1: sampling_rate %2 is not a positive number").arg(path_).arg(rate));
        return rate;
    }

    // The free-text root attribute "info", empty if absent or unreadable (it is only a description).
    QString info() const {
        if (H5Aexists(file_, "info") <= 0) return {};
        Handle attr(H5Aopen(file_, "info", H5P_DEFAULT), H5Aclose);
        Handle type(attr.valid() ? H5Aget_type(attr) : -1, H5Tclose);
        if (!type.valid() || H5Tget_class(type) != H5T_STRING) return {};
        if (H5Tis_variable_str(type) > 0) {
            Handle memType(H5Tcopy(H5T_C_S1), H5Tclose);
            H5Tset_size(memType, H5T_VARIABLE);
            H5Tset_cset(memType, H5Tget_cset(type));
            char* text = nullptr;
            if (H5Aread(attr, memType, &text) < 0 || !text) return {};
            QString s = QString::fromUtf8(text);
            H5free_memory(text);
            return s;
        }
        std::vector<char> buffer(H5Tget_size(type) + 1, '\0');
        if (H5Aread(attr, type, buffer.data()) < 0) return {};
        return QString::fromUtf8(buffer.data());
    }

private:
    QString path_;
    Handle file_;
};

struct Part {
    const char* dataset;
    int columns;
    QStringList names;
    QString unit;
};

}  // namespace

QString BroadImporter::description() const {
    return QStringLiteral("BROAD benchmark trial (HDF5): IMU and optical reference orientation");
}

// BROAD is the only HDF5 format Athlos imports, so the signature decides; nothing in the file is
// parsed before read() has checked it in isolation.
bool BroadImporter::canRead(const QString&, const QByteArray& head) const { return hasSignature(head); }

namespace {

// Reads a BROAD file; the caller holds the HDF5 lock.
Expected<ImportResult> readBroad(const QString& file, const Progress& progress) {
    BroadFile broad(file);
    if (Status s = broad.open(); !s) return s.error();
    const auto rate = broad.samplingRate();
    if (!rate) return rate.error();

    const std::vector<Part> imuParts{{"imu_acc", 3, {"acc_x", "acc_y", "acc_z"}, "m/s^2"},
                                     {"imu_gyr", 3, {"gyr_x", "gyr_y", "gyr_z"}, "rad/s"},
                                     {"imu_mag", 3, {"mag_x", "mag_y", "mag_z"}, "uT"}};
    const std::vector<Part> referenceParts{{"opt_quat", 4, {"qw", "qx", "qy", "qz"}, "1"},
                                           {"movement", 1, {"movement"}, "1"},
                                           {"opt_pos", 3, {"pos_x", "pos_y", "pos_z"}, "m"}};
    hsize_t rows = 0;
    int done = 0;
    // Reads the parts side by side into one N×C block.
    auto assemble = [&](const std::vector<Part>& parts, StreamInfo& info) -> Expected<StreamData> {
        int width = 0;
        for (const Part& part : parts) width += part.columns;
        StreamData data;
        int at = 0;
        for (const Part& part : parts) {
            if (progress.isCancelled()) return makeError(QStringLiteral("cancelled"));
            hsize_t n = 0;
            auto block = broad.matrix(part.dataset, part.columns, n);
            if (!block) return block.error();
            if (rows == 0 && done == 0) rows = n;
            if (n != rows)
                return makeError(QStringLiteral("%1: dataset '%2' has %3 rows, imu_acc has %4")
                                     .arg(file, QLatin1String(part.dataset))
                                     .arg(n)
                                     .arg(rows));
            if (data.columns == 0) data = StreamData(rows, width);
            for (hsize_t r = 0; r < rows; ++r)
                for (int c = 0; c < part.columns; ++c) data.at(r, at + c) = (*block)[r * part.columns + c];
            for (const QString& name : part.names) info.columns.push_back({name, part.unit});
            at += part.columns;
            progress.report(double(++done) / 6.0, QStringLiteral("Reading %1").arg(part.dataset));
        }
        for (hsize_t r = 0; r < rows; ++r) data.t[r] = double(r) / *rate;
        return data;
    };

    const QString info = broad.info();
    auto describe = [&](StreamInfo& s, const char* name, const char* kind, const char* frame) {
        s.name = QLatin1String(name);
        s.kind = QLatin1String(kind);
        s.frame = QLatin1String(frame);
        s.attributes.insert(QStringLiteral("sampling_rate"), *rate);
        if (!info.isEmpty()) s.attributes.insert(QStringLiteral("info"), info);
    };
    StreamInfo imuInfo, referenceInfo;
    describe(imuInfo, "imu", "imu", "sensor");
    describe(referenceInfo, "reference", "reference", "ENU");
    auto imu = assemble(imuParts, imuInfo);
    if (!imu) return imu.error();
    auto reference = assemble(referenceParts, referenceInfo);
    if (!reference) return reference.error();
    if (rows == 0) return makeError(QStringLiteral("%1: the datasets are empty").arg(file));

    ImportResult result;
    result.items.push_back({QStringLiteral("imu"), Stream(std::move(imuInfo), std::move(*imu))});
    result.items.push_back({QStringLiteral("reference"), Stream(std::move(referenceInfo), std::move(*reference))});
    return result;
}

}  // namespace

Expected<ImportResult> BroadImporter::read(const QString& file, const ImportOptions&, const Progress& progress) const {
    const auto guard = h5::lock();  // HDF5 may be built without thread safety; the store shares this lock
    // libhdf5 can crash or hang on damaged files: read the whole file in a child process first.
    if (!VerifiedFiles::contains(file)) {
        const Status checked = runIsolated(
            QStringLiteral("'%1'").arg(file),
            [&]() -> Status {
                auto result = readBroad(file, Progress{});
                return result ? Status{} : Status(result.error());
            },
            IsolatedRunParams{isolatedTimeoutFor(VerifiedFiles::sizeOf(file)), 0});
        if (!checked) return checked.error();
        VerifiedFiles::remember(file);
    }
    return readBroad(file, progress);
}

}  // namespace athlos
