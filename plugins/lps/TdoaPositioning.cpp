#include "plugins/lps/TdoaPositioning.h"

#include <numbers>

namespace athlos::lps {

TdoaPositioning::TdoaPositioning(const Params& params, BeaconLayout layout, TrackGeometry track,
                                 HeadingFunction orientationHeading)
    : params_(params),
      layout_(std::move(layout)),
      track_(std::move(track)),
      orientationHeading_(std::move(orientationHeading)),
      referenceDistance_(referenceDistances(layout_)),
      solver_(params.solver),
      selection_(params.selection),
      history_(5, params.maxWarmStartGap) {}

void TdoaPositioning::reset() {
    last_ = {};
    history_.clear();
}

std::optional<BeaconSelection::View> TdoaPositioning::view(double t) const {
    const auto position = history_.median(t);
    if (!position) return std::nullopt;
    std::optional<double> heading;
    switch (params_.heading) {
        case HeadingSource::Track:
            heading = track_.headingAt(position->head<2>()) + (params_.clockwise ? std::numbers::pi : 0.0);
            break;
        case HeadingSource::Orientation:
            if (orientationHeading_) heading = orientationHeading_(t);
            break;
        case HeadingSource::Motion:
            heading = history_.motionHeading(t);
            break;
    }
    if (!heading) return std::nullopt;
    return BeaconSelection::View{*position, *heading};
}

TagFix TdoaPositioning::update(const TdoaEpoch& epoch) {
    input_.assign(epoch, layout_, referenceDistance_);
    const bool warm = last_.valid && epoch.t - last_.t <= params_.maxWarmStartGap;
    std::optional<BeaconSelection::View> v;
    if (params_.selection.method == BeaconSelection::Method::FieldOfView) v = view(epoch.t);
    TagFix fix;
    if (input_.size() >= params_.selection.minBeacons)
        fix = selection_.solve(input_, solver_, warm ? &last_ : nullptr, v ? &*v : nullptr);
    fix.t = epoch.t;
    if (fix.valid) {
        last_ = fix;
        history_.push(fix);
    }
    return fix;
}

std::optional<std::vector<TagFix>> TdoaPositioning::run(const std::vector<TdoaEpoch>& epochs,
                                                        const Progress& progress) {
    std::vector<TdoaEpoch> screened;
    if (params_.screening.method != TdoaScreening::Method::None)
        screened = TdoaScreening(params_.screening).screen(epochs, layout_.size(), &screened_);
    const std::vector<TdoaEpoch>& in = screened.empty() ? epochs : screened;
    std::vector<TagFix> fixes;
    fixes.reserve(in.size());
    for (std::size_t k = 0; k < in.size(); ++k) {
        if (k % 256 == 0) {
            if (progress.isCancelled()) return std::nullopt;
            progress.report(double(k) / double(in.size()), QStringLiteral("positioning"));
        }
        fixes.push_back(update(in[k]));
    }
    progress.report(1.0);
    return fixes;
}

}  // namespace athlos::lps
