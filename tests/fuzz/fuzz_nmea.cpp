// Fuzz target: the NMEA-0183 importer (RMC, GGA, VTG merged per epoch), on the text in memory.
#include "FuzzInput.h"
#include "core/io/NmeaImporter.h"

using namespace athlos;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const QByteArray text = fuzz::bytes(data, size);
    (void)NmeaImporter().canRead(QStringLiteral("fuzz.nmea"), text.left(4096));
    (void)NmeaImporter::parse(text, QStringLiteral("fuzz.nmea"));
    return 0;
}
