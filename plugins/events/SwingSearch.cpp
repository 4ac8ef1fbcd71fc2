#include "plugins/events/SwingSearch.h"

#include "core/processing/Translator.h"

#include <limits>

namespace athlos::events {

namespace {
constexpr Translator tr{"athlos::events"};
constexpr double kInf = std::numeric_limits<double>::infinity();
}  // namespace

ParameterSpecs swingSearchParameters(const SwingSearch& d, const QString& maxStrideHelp) {
    return {
        ParameterSpec::number(QStringLiteral("swing_threshold"), d.swingThreshold, 0.0, kInf, QStringLiteral("rad/s"),
                              tr("Minimum mid-swing angular velocity of a stride (walking peaks are 4–7 rad/s, "
                                 "Rampp et al. 2015).")),
        ParameterSpec::number(QStringLiteral("min_stride"), d.minStrideTime, 0.05, kInf, QStringLiteral("s"),
                              tr("Shortest stride; closer swing peaks count as one.")),
        ParameterSpec::number(QStringLiteral("max_stride"), d.maxStrideTime, 0.1, kInf, QStringLiteral("s"),
                              maxStrideHelp),
        ParameterSpec::number(QStringLiteral("tc_window"), d.tcWindow, 0.01, kInf, QStringLiteral("s"),
                              tr("Search window for toe-off before the swing peak.")),
        ParameterSpec::number(QStringLiteral("ic_window"), d.icWindow, 0.01, kInf, QStringLiteral("s"),
                              tr("Search window for initial contact after the swing peak.")),
    };
}

Expected<SwingSearch> readSwingSearch(const RunContext& c) {
    SwingSearch s;
    s.swingThreshold = c.number(QStringLiteral("swing_threshold"));
    s.minStrideTime = c.number(QStringLiteral("min_stride"));
    s.maxStrideTime = c.number(QStringLiteral("max_stride"));
    s.tcWindow = c.number(QStringLiteral("tc_window"));
    s.icWindow = c.number(QStringLiteral("ic_window"));
    if (s.maxStrideTime <= s.minStrideTime)
        return makeError(QStringLiteral("max_stride: %1 s must be longer than min_stride (%2 s)")
                             .arg(s.maxStrideTime)
                             .arg(s.minStrideTime));
    return s;
}

}  // namespace athlos::events
