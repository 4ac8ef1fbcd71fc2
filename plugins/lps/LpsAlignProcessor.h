#pragma once
// `lps-align`: moves a beacon table (and its reference node) so that two or three venue marks land
// where the user says (thesis §3.1.2 step 9). Marks come from the `marks` parameter
// "x,y,z>X,Y,Z; …" (LPS coordinates measured with the tag > desired coordinates) or from an optional
// marks table with columns x, y, z, target_x, target_y, target_z (m). mode=yaw keeps the frame
// level (two marks suffice), mode=full is a Kabsch rotation (three non-collinear marks).
#include "core/processing/Processor.h"
#include "plugins/lps/FrameAlignment.h"

namespace athlos::lps {

class LpsAlignProcessor : public Processor {
public:
    QString id() const override { return QStringLiteral("lps-align"); }
    QString name() const override;
    QString description() const override;
    QString version() const override { return QStringLiteral("1.0"); }
    ParameterSpecs parameters() const override;
    QList<InputSpec> inputs() const override;
    QList<OutputSpec> outputs() const override;
    Status prepare(const RunContext& context) const override;
    Expected<std::vector<ProcessorOutput>> run(const RunContext& context) const override;

    // "x,y,z>X,Y,Z; …" → (from, to) pairs; errors name the offending mark.
    static Expected<std::pair<std::vector<Vector3>, std::vector<Vector3>>> parseMarks(const QString& text);
};

}  // namespace athlos::lps
