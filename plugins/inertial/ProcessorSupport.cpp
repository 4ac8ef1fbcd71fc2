#include "plugins/inertial/ProcessorSupport.h"

namespace athlos::inertial {

Expected<LoadedStream> loadInput(const RunContext& context, int index) {
    const QString path = index < context.inputCount() ? context.inputPath(index) : QString();
    const Stream* stream = context.stream(index);
    if (!stream) return makeError(QStringLiteral("input stream '%1' is missing").arg(path));
    auto data = stream->data();
    if (!data) return makeError(QStringLiteral("cannot read input stream '%1': %2").arg(path, data.message()));
    return LoadedStream{stream, std::move(data).value()};
}

int tripleIndex(const StreamInfo& info, const QString& prefix) {
    const int x = info.columnIndex(prefix + QStringLiteral("x"));
    if (x < 0 || info.columnIndex(prefix + QStringLiteral("y")) != x + 1 || info.columnIndex(prefix + QStringLiteral("z")) != x + 2)
        return -1;
    return x;
}

Expected<ImuColumns> imuColumns(const StreamInfo& info, const QString& path, bool requireMag) {
    ImuColumns c;
    c.acc = tripleIndex(info, QStringLiteral("acc_"));
    c.gyr = tripleIndex(info, QStringLiteral("gyr_"));
    c.mag = tripleIndex(info, QStringLiteral("mag_"));
    const QString have = info.columnNames().join(QStringLiteral(", "));
    if (c.acc < 0 || c.gyr < 0)
        return makeError(QStringLiteral("stream '%1' needs adjacent columns acc_x, acc_y, acc_z and gyr_x, gyr_y, gyr_z "
                                        "(it has: %2)").arg(path, have));
    if (requireMag && c.mag < 0)
        return makeError(QStringLiteral("mode: 9d needs magnetometer columns mag_x, mag_y, mag_z in '%1' (it has: %2); "
                                        "use mode=6d").arg(path, have));
    return c;
}

Stream makeStream(const QString& kind, const QString& frame, const QStringList& names, const QStringList& units,
                  StreamData data, QJsonObject attributes) {
    StreamInfo info;
    info.kind = kind;
    info.frame = frame;
    for (int i = 0; i < names.size(); ++i) info.columns.push_back({names[i], units.value(i, QStringLiteral("1"))});
    info.attributes = std::move(attributes);
    return Stream(std::move(info), std::move(data));
}

Expected<double> samplingInterval(const StreamData& data, const QString& path) {
    if (data.rows() < 2)
        return makeError(QStringLiteral("stream '%1' has %2 sample(s); at least 2 are needed").arg(path).arg(data.rows()));
    const double ts = data.medianInterval();
    if (!(ts > 0.0)) return makeError(QStringLiteral("stream '%1' has no positive sampling interval").arg(path));
    return ts;
}

}  // namespace athlos::inertial
