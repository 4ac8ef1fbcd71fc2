#include "plugins/events/VectorColumns.h"

namespace athlos::events {

Expected<int> vectorColumns(const RunContext& c, int input, const QString& prefix, const QString& unit,
                            const QString& processor) {
    const Stream* stream = c.stream(input);
    if (!stream) return makeError(QStringLiteral("input '%1' was not given").arg(c.inputRole(input)));
    const StreamInfo& info = stream->info();
    const int i = info.columnIndex(prefix + QLatin1Char('x'));
    if (i < 0 || info.columnIndex(prefix + QLatin1Char('y')) != i + 1 ||
        info.columnIndex(prefix + QLatin1Char('z')) != i + 2)
        return c.inputError(input, QStringLiteral("needs adjacent columns %1x, %1y, %1z (it has: %2)")
                                       .arg(prefix, info.columnNames().join(QStringLiteral(", "))));
    for (int k = 0; k < 3; ++k) {
        const auto& column = info.columns[std::size_t(i + k)];
        if (!column.unit.isEmpty() && column.unit != unit)
            return c.inputError(
                input,
                QStringLiteral("column %1 is in '%2'; %3 expects %4").arg(column.name, column.unit, processor, unit));
    }
    return i;
}

}  // namespace athlos::events
