// Fuzz target: the gaitmap importer (CSV with a sensor and an axis header row).
#include "FuzzInput.h"
#include "core/io/GaitmapImporter.h"

#include <algorithm>

using namespace athlos;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const fuzz::InputFile input(data, size, QStringLiteral(".csv"));
    (void)GaitmapImporter().canRead(input.path(), fuzz::bytes(data, std::min<size_t>(size, 4096)));
    ImportOptions options;
    options.format = QStringLiteral("gaitmap");
    options.target = QStringLiteral("walk");
    (void)importFile(input.path(), options);
    return 0;
}
