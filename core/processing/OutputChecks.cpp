#include "core/processing/OutputChecks.h"

#include <algorithm>
#include <cmath>

namespace athlos {
namespace {

Status checkStream(const Stream& stream, const QString& path) {
    if (stream.info().rows == 0)
        return makeError(
            QStringLiteral("output '%1' would be empty (0 rows): the run produced nothing to store").arg(path));
    if (!stream.isLoaded() || stream.info().columns.empty()) return {};  // file-backed: checked when it was written
    auto data = stream.data();
    if (!data) return data.error();
    const auto& values = (*data)->values;
    if (!values.empty() && std::none_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); }))
        return makeError(QStringLiteral("output '%1': every value of its %2 rows × %3 columns is NaN or infinite: "
                                        "the run produced nothing to store")
                             .arg(path)
                             .arg((*data)->rows())
                             .arg((*data)->columns));
    return {};
}

}  // namespace

Status checkOutputUseful(const ProcessorOutput& output, const QString& path) {
    if (const auto* stream = std::get_if<Stream>(&output.item)) return checkStream(*stream, path);
    if (const auto* table = std::get_if<Table>(&output.item); table && table->rows() == 0)
        return makeError(
            QStringLiteral("output table '%1' would be empty (0 rows): the run produced nothing to store").arg(path));
    return {};
}

}  // namespace athlos
