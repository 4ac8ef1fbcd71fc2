// Fuzz target: the import preview (format and kind detection, first rows, column → channel/unit
// mapping) and the dry run of an import with the options the preview suggests.
#include "FuzzInput.h"
#include "core/io/ImportPreview.h"

using namespace athlos;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const fuzz::InputFile input(data, size, QStringLiteral(".csv"));
    auto preview = previewFile(input.path(), QStringLiteral("auto"), 20);
    if (!preview) return 0;
    for (const PreviewColumn& column : preview->columns) {
        (void)detectChannel(column.source);
        (void)storedUnitFor(preview->kind, column.channel, column.unit, column.time);
    }
    ImportOptions options = suggestedOptions(*preview);
    options.target = QStringLiteral("rec");
    (void)checkImport(input.path(), options);
    return 0;
}
