#include "ui/venue/VenuePlot.h"

#include "core/model/Table.h"
#include "ui/PlotStyle.h"
#include "ui/venue/EqualAspectFrame.h"
#include "ui/venue/TrackOverlay.h"

#include <QVBoxLayout>
#include <qcustomplot.h>

namespace athlos::ui {

VenuePlot::VenuePlot(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    plot_ = new QCustomPlot(this);
    PlotStyle::apply(plot_);
    plot_->xAxis->setLabel(tr("x [m]"));
    plot_->yAxis->setLabel(tr("y [m]"));
    plot_->legend->setVisible(true);
    layout->addWidget(plot_);
    overlay_ = std::make_unique<TrackOverlay>(plot_);
    aspect_ = new EqualAspectFrame(plot_);
    walk_ = new QCPCurve(plot_->xAxis, plot_->yAxis);
    walk_->setLineStyle(QCPCurve::lsNone);
    walk_->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, QColor(150, 150, 150), 3));
    walk_->setName(tr("Walk"));
}

VenuePlot::~VenuePlot() = default;

void VenuePlot::setTrack(const TrackGeometry& track) {
    overlay_->setTrack(track);
    refit();
}

QCPCurve* VenuePlot::beaconCurve(const QString& layer) const {
    for (const Layer& l : layers_)
        if (l.name == layer) return l.curve;
    return nullptr;
}

void VenuePlot::removeBeacons(const QString& layer) {
    for (int i = 0; i < layers_.size(); ++i) {
        if (layers_[i].name != layer) continue;
        plot_->removePlottable(layers_[i].curve);
        for (QCPAbstractItem* item : std::as_const(layers_[i].labels)) plot_->removeItem(item);
        layers_.removeAt(i);
        return;
    }
}

void VenuePlot::setBeacons(const QString& layer, const Table& beacons, const QColor& color) {
    removeBeacons(layer);
    const TableColumn* id = beacons.column(QStringLiteral("id"));
    const TableColumn* x = beacons.column(QStringLiteral("x"));
    const TableColumn* y = beacons.column(QStringLiteral("y"));
    if (!x || !y || x->isText || y->isText) return;
    Layer l;
    l.name = layer;
    l.curve = new QCPCurve(plot_->xAxis, plot_->yAxis);
    l.curve->setLineStyle(QCPCurve::lsNone);
    l.curve->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, QPen(color, 2), QBrush(color.lighter(160)), 9));
    l.curve->setName(layer);
    QVector<double> xs(x->numbers.begin(), x->numbers.end()), ys(y->numbers.begin(), y->numbers.end());
    l.curve->setData(xs, ys);
    if (id && id->isText) {
        for (int i = 0; i < xs.size() && i < id->texts.size(); ++i) {
            auto* label = new QCPItemText(plot_);
            label->position->setCoords(xs[i], ys[i]);
            label->setPositionAlignment(Qt::AlignLeft | Qt::AlignBottom);
            label->setText(id->texts[i]);
            label->setColor(color);
            l.labels.append(label);
        }
    }
    layers_.append(l);
    refit();
}

void VenuePlot::setWalk(const QVector<double>& x, const QVector<double>& y) {
    walk_->setData(x, y);
    refit();
}

void VenuePlot::refit() { aspect_->frameAll(0.08); }

}  // namespace athlos::ui
