#pragma once
// The venue seen from above: the track's lanes, beacon layouts (labelled dots, one style per layout)
// and a walk path, with equal metres per pixel on both axes. Used by the LPS calibration wizard to
// compare the initial and the calibrated beacon positions on the real venue.
#include "core/geometry/TrackGeometry.h"

#include <QColor>
#include <QList>
#include <QString>
#include <QVector>
#include <QWidget>
#include <memory>

class QCPAbstractItem;
class QCPCurve;
class QCustomPlot;

namespace athlos {
struct Table;
}

namespace athlos::ui {

class EqualAspectFrame;
class TrackOverlay;

class VenuePlot : public QWidget {
    Q_OBJECT

public:
    explicit VenuePlot(QWidget* parent = nullptr);
    ~VenuePlot() override;

    void setTrack(const TrackGeometry& track);
    // Replaces the layout called `layer` (e.g. "initial", "calibrated"); an empty table removes it.
    void setBeacons(const QString& layer, const Table& beacons, const QColor& color);
    void removeBeacons(const QString& layer);
    void setWalk(const QVector<double>& x, const QVector<double>& y);
    void refit();

    QCustomPlot* plot() const { return plot_; }
    TrackOverlay* overlay() const { return overlay_.get(); }
    QCPCurve* beaconCurve(const QString& layer) const;
    QCPCurve* walkCurve() const { return walk_; }

private:
    struct Layer {
        QString name;
        QCPCurve* curve = nullptr;
        QList<QCPAbstractItem*> labels;
    };

    QCustomPlot* plot_ = nullptr;
    std::unique_ptr<TrackOverlay> overlay_;
    QCPCurve* walk_ = nullptr;
    EqualAspectFrame* aspect_ = nullptr;
    QList<Layer> layers_;
};

}  // namespace athlos::ui
