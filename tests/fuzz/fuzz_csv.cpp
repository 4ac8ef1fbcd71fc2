// Fuzz target: the CSV tokenizer and the CSV importer (generic CSV, TDoA long format t,beacon,dt,
// beacon tables id,x,y,z; the kind is detected from the columns or given by a "# fuzz:" line,
// see FuzzOptions.h).
#include "FuzzInput.h"
#include "FuzzOptions.h"
#include "core/io/CsvImporter.h"
#include "core/io/CsvReader.h"

#include <algorithm>
#include <string>
#include <vector>

using namespace athlos;

namespace {

// The tokenizer on an exact-size heap copy: a read past the end is an ASan report here, where the
// memory-mapped file of an import has slack up to the end of the page.
void tokenize(const uint8_t* data, size_t size) {
    const std::vector<char> bytes(data, data + size);
    CsvReader reader(bytes.data(), bytes.data() + bytes.size());
    QStringList header;
    if (!reader.readHeader(header)) return;
    std::string text;
    double value = 0;
    for (size_t records = 0; records <= size && reader.nextRecord(); ++records) {
        for (int i = 0; i < header.size(); ++i) {
            // Alternate the two ways of reading a field, as importers do for number and id columns.
            if (i % 2 == 0) {
                if (reader.number(value) == CsvReader::Field::Missing) break;
            } else if (!reader.text(text)) {
                break;
            }
            (void)reader.lastField();
        }
        (void)reader.fieldsOnLine();
        while (!reader.finishRecord())  // more fields than the header: read them as text
            if (!reader.text(text)) break;
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    tokenize(data, size);
    const fuzz::InputFile input(data, size, QStringLiteral(".csv"));
    ImportOptions options = fuzz::optionsFromInput(fuzz::bytes(data, size));
    options.format = QStringLiteral("csv");
    (void)CsvImporter().canRead(input.path(), fuzz::bytes(data, std::min<size_t>(size, 4096)));
    (void)importFile(input.path(), options);
    return 0;
}
