// Fuzz target: the BROAD importer (HDF5 with imu_acc, imu_gyr, imu_mag, opt_quat, opt_pos,
// movement and a sampling_rate attribute), on the input written to a temporary .hdf5 file.
// A crash inside libhdf5 on a damaged file is a finding too: the importer must not pass it
// anything that makes it fail that way, and the project needs to know which files do.
#include "FuzzInput.h"
#include "core/io/BroadImporter.h"

#include <algorithm>

using namespace athlos;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const fuzz::InputFile input(data, size, QStringLiteral(".hdf5"));
    (void)BroadImporter().canRead(input.path(), fuzz::bytes(data, std::min<size_t>(size, 4096)));
    ImportOptions options;
    options.format = QStringLiteral("broad");
    options.target = QStringLiteral("trial");
    (void)importFile(input.path(), options);
    return 0;
}
