// Writes the binary seeds of the fuzz corpus that cannot be cut from the shared recordings
// (those are megabytes): a tiny BROAD trial (HDF5), small projects (.athlos) and an annotation
// journal, all made with the same code paths as real files. Run once when the formats change:
//   cmake --build build --target athlos_fuzz_seeds && build/bin/athlos_fuzz_seeds tests/fuzz/corpus
#include "core/model/AnnotationEdit.h"
#include "core/model/AnnotationJournal.h"
#include "core/model/Project.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <cmath>
#include <cstdio>
#include <hdf5.h>
#include <vector>

using namespace athlos;

namespace {

void writeMatrix(hid_t file, const char* name, hsize_t rows, hsize_t columns, double offset) {
    const hsize_t dims[2] = {rows, columns};
    const hid_t space = H5Screate_simple(columns == 1 ? 1 : 2, dims, nullptr);
    const hid_t d = H5Dcreate2(file, name, H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    std::vector<double> v(rows * columns);
    for (size_t i = 0; i < v.size(); ++i) v[i] = offset + 0.01 * double(i);
    H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
    H5Dclose(d);
    H5Sclose(space);
}

// A BROAD trial of 8 samples: the datasets and attribute the importer reads, nothing else.
bool writeBroad(const QString& path) {
    const hid_t f = H5Fcreate(QFile::encodeName(path).constData(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    if (f < 0) return false;
    constexpr hsize_t n = 8;
    writeMatrix(f, "imu_acc", n, 3, 9.0);
    writeMatrix(f, "imu_gyr", n, 3, 0.1);
    writeMatrix(f, "imu_mag", n, 3, 30.0);
    writeMatrix(f, "opt_quat", n, 4, 0.5);
    writeMatrix(f, "opt_pos", n, 3, 1.0);
    {
        const hsize_t dims[1] = {n};
        const hid_t space = H5Screate_simple(1, dims, nullptr);
        const hid_t d = H5Dcreate2(f, "movement", H5T_NATIVE_HBOOL, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
        const unsigned char movement[n] = {0, 0, 1, 1, 1, 1, 0, 0};
        H5Dwrite(d, H5T_NATIVE_HBOOL, H5S_ALL, H5S_ALL, H5P_DEFAULT, movement);
        H5Dclose(d);
        H5Sclose(space);
    }
    const hid_t scalar = H5Screate(H5S_SCALAR);
    const hid_t a = H5Acreate2(f, "sampling_rate", H5T_IEEE_F64LE, scalar, H5P_DEFAULT, H5P_DEFAULT);
    const double rate = 285.71;
    H5Awrite(a, H5T_NATIVE_DOUBLE, &rate);
    H5Aclose(a);
    H5Sclose(scalar);
    return H5Fclose(f) >= 0;
}

Stream imuStream(int rows) {
    StreamInfo info;
    info.kind = QStringLiteral("imu");
    info.frame = QStringLiteral("sensor");
    info.columns = {{"acc_x", "m/s^2"}, {"acc_y", "m/s^2"}, {"gyr_z", "rad/s"}};
    info.attributes = QJsonObject{{"sampling_rate", 100.0}};
    StreamData data(size_t(rows), 3);
    for (int i = 0; i < rows; ++i) {
        data.t[size_t(i)] = 0.01 * i;
        for (int c = 0; c < 3; ++c) data.at(size_t(i), c) = std::sin(0.1 * i + c);
    }
    return Stream(info, data);
}

Table beaconTable() {
    Table table;
    table.kind = QStringLiteral("beacons");
    TableColumn id{QStringLiteral("id"), {}, true, {}, {QStringLiteral("A1"), QStringLiteral("A2")}};
    TableColumn x{QStringLiteral("x"), QStringLiteral("m"), false, {0.0, 10.0}, {}};
    TableColumn y{QStringLiteral("y"), QStringLiteral("m"), false, {0.0, 5.0}, {}};
    table.columns = {id, x, y};
    return table;
}

Annotation annotation(const char* label, double t0) {
    return Annotation{QString::fromLatin1(label), t0, t0 + 0.5, QStringLiteral("coach"), 1.0, QStringLiteral("manual")};
}

// minimal: one stream. full: a stream, a text table, annotations, geometry, classes, a pipeline.
bool writeProject(const QString& path, bool full) {
    auto project = Project::create(path, QStringLiteral("football"));
    project->putStream(QStringLiteral("run/imu"), imuStream(full ? 12 : 4));
    if (full) {
        project->putTable(QStringLiteral("venue/beacons"), beaconTable());
        Recording& run = project->ensureRecording(QStringLiteral("run"));
        run.metadata = QJsonObject{{"athlete", "Anna Berg"}};
        run.annotations = {annotation("tackle", 0.02), annotation("pass", 0.05)};
        project->annotationClasses() << QStringLiteral("tackle") << QStringLiteral("pass");
        project->geometry()[QStringLiteral("pitch")] =
            QJsonObject{{"type", "football"}, {"length", 105}, {"width", 68}};
        project->pipelineHistory().append(
            QJsonObject{{"steps", QJsonArray{QJsonObject{{"processor", "butterworth"}}}}});
    }
    const Status s = project->save();
    if (!s) std::fprintf(stderr, "%s\n", qUtf8Printable(s.message()));
    return bool(s);
}

// A journal as the editor writes it: the base digest, then one edit of each kind.
bool writeJournal(const QString& folder, const QString& name) {
    const QString projectPath = QDir(folder).filePath(QStringLiteral(".journal-base.athlos"));
    auto project = Project::create(projectPath, QStringLiteral("football"));
    project->ensureRecording(QStringLiteral("rec"));
    project->annotationClasses() << QStringLiteral("tackle");
    AnnotationJournal journal(projectPath);
    const AnnotationEdit edits[] = {
        AnnotationEdit::addClass(QStringLiteral("pass")),
        AnnotationEdit::insert(QStringLiteral("rec"), 0, annotation("tackle", 1.0)),
        AnnotationEdit::replace(QStringLiteral("rec"), 0, annotation("tackle", 1.0), annotation("pass", 2.0)),
        AnnotationEdit::remove(QStringLiteral("rec"), 0, annotation("pass", 2.0)),
    };
    for (const AnnotationEdit& e : edits) {
        if (!journal.append(e, project.get()) || !e.apply(*project)) return false;
    }
    QFile::remove(QDir(folder).filePath(name));
    return QFile::rename(AnnotationJournal::pathFor(projectPath), QDir(folder).filePath(name));
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: athlos_fuzz_seeds <tests/fuzz/corpus>\n");
        return 2;
    }
    const QDir corpus(QString::fromLocal8Bit(argv[1]));
    for (const char* sub : {"broad", "project", "journal"}) corpus.mkpath(QString::fromLatin1(sub));
    bool ok = writeBroad(corpus.filePath(QStringLiteral("broad/tiny.hdf5")));
    ok = writeProject(corpus.filePath(QStringLiteral("project/minimal.athlos")), false) && ok;
    ok = writeProject(corpus.filePath(QStringLiteral("project/full.athlos")), true) && ok;
    ok = writeJournal(corpus.filePath(QStringLiteral("journal")), QStringLiteral("edits.journal")) && ok;
    std::printf("%s\n", ok ? "seeds written" : "failed");
    return ok ? 0 : 1;
}
