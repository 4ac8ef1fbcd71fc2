#include "ui/views/StickFigureView.h"

#include "core/model/Project.h"
#include "ui/TimeController.h"
#include "ui/ToolRegistry.h"
#include "ui/Workspace.h"
#include "ui/WorkspaceNotifier.h"

#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QDockWidget>
#include <QHBoxLayout>
#include <QLabel>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <limits>

namespace athlos::ui {

using math::Vec3;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// The joints of a body-com joint stream, in its column order (plugins/body/Anthropometry.h, Joint).
constexpr std::array<const char*, 15> kJoints{"lumbar",      "cervical",    "head-vertex",   "right-shoulder",
                                              "right-elbow", "right-wrist", "left-shoulder", "left-elbow",
                                              "left-wrist",  "right-hip",   "right-knee",    "right-ankle",
                                              "left-hip",    "left-knee",   "left-ankle"};
enum {
    Lumbar,
    Cervical,
    Vertex,
    RShoulder,
    RElbow,
    RWrist,
    LShoulder,
    LElbow,
    LWrist,
    RHip,
    RKnee,
    RAnkle,
    LHip,
    LKnee,
    LAnkle
};
// Bones (joint pairs) and whether they are on the left side (drawn lighter).
struct Bone {
    int a, b;
    bool left;
};
constexpr std::array<Bone, 14> kBones{{{Lumbar, Cervical, false},
                                       {Cervical, Vertex, false},
                                       {Cervical, RShoulder, false},
                                       {RShoulder, RElbow, false},
                                       {RElbow, RWrist, false},
                                       {Cervical, LShoulder, true},
                                       {LShoulder, LElbow, true},
                                       {LElbow, LWrist, true},
                                       {Lumbar, RHip, false},
                                       {RHip, RKnee, false},
                                       {RKnee, RAnkle, false},
                                       {Lumbar, LHip, true},
                                       {LHip, LKnee, true},
                                       {LKnee, LAnkle, true}}};

bool isJointStream(const Stream& s) {
    if (s.kind() != QLatin1String("joint-centres") ||
        s.info().attributes.value(QStringLiteral("origin")).toString() != QLatin1String("lumbar joint centre"))
        return false;
    for (const char* j : kJoints)
        if (s.info().columnIndex(QLatin1String(j) + QStringLiteral("_x")) < 0) return false;
    return true;
}

}  // namespace

// The drawing surface: the figure fitted to the widget, drag to rotate.
class StickFigureCanvas : public QWidget {
public:
    explicit StickFigureCanvas(StickFigureView* view) : QWidget(view), view_(view) {
        setMinimumSize(240, 240);
        setObjectName(QStringLiteral("stickFigureCanvas"));
        setCursor(Qt::OpenHandCursor);
    }

protected:
    void paintEvent(QPaintEvent*) override {
        QPainter p(this);
        p.setRenderHint(QPainter::Antialiasing);
        p.fillRect(rect(), palette().base());
        if (view_->current_ < 0) {
            p.setPen(palette().text().color());
            p.drawText(rect(), Qt::AlignCenter | Qt::TextWordWrap,
                       StickFigureView::tr("No body-com result in this project; run body-com first."));
            return;
        }
        // A fixed scale: 2.2 m of the figure fit the smaller side; the lumbar joint a little above the centre.
        const double scale = std::min(width(), height()) / 2.2;
        const QPointF origin(width() / 2.0, height() * 0.42);
        const auto screen = [&](const Vec3& v) {
            const QPointF q = view_->project(v);
            return QPointF(origin.x() + scale * q.x(), origin.y() - scale * q.y());
        };
        // Ground reference: the vertical through the lumbar joint and a horizontal bar at the mean ankle height.
        const Vec3 ankles = 0.5 * (view_->joint(RAnkle) + view_->joint(LAnkle));
        p.setPen(QPen(palette().mid().color(), 1, Qt::DashLine));
        p.drawLine(screen(Vec3(0, 0, ankles.z() - 0.05)), screen(Vec3(0, 0, 0.9)));
        // CoM trajectory over ±1 s (in the current view) and the CoM.
        const std::size_t k = std::size_t(view_->current_);
        if (!view_->com_.empty()) {
            const double t0 = view_->t_[k];
            QPainterPath path;
            bool started = false;
            const auto first = std::lower_bound(view_->t_.begin(), view_->t_.end(), t0 - 1.0) - view_->t_.begin();
            for (std::size_t i = std::size_t(first); i < view_->t_.size() && view_->t_[i] <= t0 + 1.0; ++i) {
                if (!view_->com_[i].allFinite()) continue;
                const QPointF s = screen(view_->com_[i]);
                if (!started) {
                    path.moveTo(s);
                    started = true;
                } else {
                    path.lineTo(s);
                }
            }
            p.setPen(QPen(QColor(0xd5, 0x5e, 0x00, 150), 1.5));
            p.drawPath(path);
        }
        // Bones: the left side lighter; then the joints.
        for (const Bone& b : kBones) {
            p.setPen(
                QPen(b.left ? QColor(0x56, 0xb4, 0xe9) : QColor(0x00, 0x72, 0xb2), 3.0, Qt::SolidLine, Qt::RoundCap));
            p.drawLine(screen(view_->joint(b.a)), screen(view_->joint(b.b)));
        }
        p.setPen(Qt::NoPen);
        p.setBrush(palette().text());
        for (int j = 0; j < 15; ++j) p.drawEllipse(screen(view_->joint(j)), 3.0, 3.0);
        if (view_->com().allFinite()) {
            p.setBrush(QColor(0xd5, 0x5e, 0x00));
            p.drawEllipse(screen(view_->com()), 6.0, 6.0);
        }
    }
    void mousePressEvent(QMouseEvent* e) override {
        last_ = e->position();
        setCursor(Qt::ClosedHandCursor);
    }
    void mouseMoveEvent(QMouseEvent* e) override {
        if (!(e->buttons() & Qt::LeftButton)) return;
        const QPointF d = e->position() - last_;
        last_ = e->position();
        view_->setViewAngles(view_->azimuth() - 0.01 * d.x(), std::clamp(view_->elevation() + 0.01 * d.y(), -1.5, 1.5));
    }
    void mouseReleaseEvent(QMouseEvent*) override { setCursor(Qt::OpenHandCursor); }

private:
    StickFigureView* view_;
    QPointF last_;
};

StickFigureView::StickFigureView(const Project* project, QWidget* parent) : QWidget(parent), project_(project) {
    streamCombo_ = new QComboBox(this);
    streamCombo_->setObjectName(QStringLiteral("streamCombo"));
    if (project_) streamCombo_->addItems(jointStreams(*project_));
    follow_ = new QCheckBox(tr("Follow the pelvis heading"), this);
    follow_->setChecked(true);
    readout_ = new QLabel(this);
    readout_->setObjectName(QStringLiteral("readout"));
    readout_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    canvas_ = new StickFigureCanvas(this);
    auto* layout = new QVBoxLayout(this);
    auto* controls = new QHBoxLayout;
    controls->addWidget(new QLabel(tr("Joints:"), this));
    controls->addWidget(streamCombo_, 1);
    controls->addWidget(follow_);
    layout->addLayout(controls);
    layout->addWidget(canvas_, 1);
    layout->addWidget(readout_);
    connect(streamCombo_, &QComboBox::currentTextChanged, this, &StickFigureView::refresh);
    connect(follow_, &QCheckBox::toggled, this, &StickFigureView::setFollowHeading);
    refresh();
}

QStringList StickFigureView::jointStreams(const Project& project) {
    QStringList list;
    for (const QString& path : project.streamPaths())
        if (const Stream* s = project.stream(path); s && isJointStream(*s)) list << path;
    return list;
}

Status StickFigureView::setStream(const QString& path) {
    if (streamCombo_->findText(path) < 0)
        return makeError(
            tr("'%1' is not a body-com joint stream (joint-centres relative to the lumbar joint)").arg(path));
    streamCombo_->setCurrentText(path);
    return {};
}

QString StickFigureView::stream() const { return streamCombo_->currentText(); }

QWidget* StickFigureView::canvas() const { return canvas_; }

void StickFigureView::setTimeController(TimeController* controller) {
    if (controller_) disconnect(controller_, nullptr, this, nullptr);
    controller_ = controller;
    if (!controller_) return;
    connect(controller_, &TimeController::cursorChanged, this, &StickFigureView::onCursorChanged);
    connect(controller_, &QObject::destroyed, this, [this] { controller_ = nullptr; });
    onCursorChanged(controller_->cursor());
}

void StickFigureView::setViewAngles(double azimuth, double elevation) {
    azimuth_ = azimuth;
    elevation_ = elevation;
    canvas_->update();
}

void StickFigureView::setFollowHeading(bool follow) {
    followHeading_ = follow;
    if (follow_->isChecked() != follow) follow_->setChecked(follow);
    canvas_->update();
}

Vec3 StickFigureView::joint(int j) const {
    return current_ < 0 ? Vec3::Constant(kNaN) : joints_[std::size_t(current_)][std::size_t(j)];
}

Vec3 StickFigureView::com() const {
    return current_ < 0 || com_.empty() ? Vec3::Constant(kNaN) : com_[std::size_t(current_)];
}

double StickFigureView::heading() const {
    if (!followHeading_ || current_ < 0) return 0.0;
    // Forward = up × (right hip − left hip), horizontal.
    const Vec3 right = joint(RHip) - joint(LHip);
    const Vec3 forward = Vec3::UnitZ().cross(right);
    return std::atan2(forward.y(), forward.x());
}

QPointF StickFigureView::project(const Vec3& p) const {
    // Look along the horizontal direction at azimuth + heading − 90° (from the athlete's right side when
    // following the heading), tilted down by the elevation; orthographic.
    const double a = heading() + azimuth_;
    const Vec3 forward(std::cos(a), std::sin(a), 0.0);  // screen right: the athlete's forward direction
    const Vec3 depth = Vec3::UnitZ().cross(forward);    // away from the viewer
    const double ce = std::cos(elevation_), se = std::sin(elevation_);
    const Vec3 up = ce * Vec3::UnitZ() - se * depth;
    return QPointF(p.dot(forward), p.dot(up));
}

QString StickFigureView::readoutText() const { return readout_->text(); }

void StickFigureView::refresh() {
    t_.clear();
    joints_.clear();
    com_.clear();
    foreAft_.clear();
    current_ = -1;
    const QString path = streamCombo_->currentText();
    const Stream* stream = project_ ? project_->stream(path) : nullptr;
    if (stream) {
        if (auto data = stream->data()) {
            const StreamData& d = **data;
            std::array<int, 15> col{};
            for (int j = 0; j < 15; ++j)
                col[std::size_t(j)] =
                    stream->info().columnIndex(QLatin1String(kJoints[std::size_t(j)]) + QStringLiteral("_x"));
            t_ = d.t;
            joints_.resize(d.rows());
            for (std::size_t k = 0; k < d.rows(); ++k)
                for (std::size_t j = 0; j < 15; ++j)
                    joints_[k][j] = Vec3(d.at(k, col[j]), d.at(k, col[j] + 1), d.at(k, col[j] + 2));
        }
        // The CoM: the main output of the same run (the joint stream is <output>-joints).
        const QString main = path.endsWith(QLatin1String("-joints")) ? path.chopped(7) : QString();
        if (const Stream* c = main.isEmpty() ? nullptr : project_->stream(main)) {
            const int cx = c->info().columnIndex(QStringLiteral("com_x"));
            const int fa = c->info().columnIndex(QStringLiteral("fore_aft"));
            auto data = c->data();
            if (cx >= 0 && data && (*data)->t == t_) {
                const StreamData& d = **data;
                com_.resize(d.rows());
                foreAft_.resize(d.rows(), kNaN);
                for (std::size_t k = 0; k < d.rows(); ++k) {
                    com_[k] = Vec3(d.at(k, cx), d.at(k, cx + 1), d.at(k, cx + 2));
                    if (fa >= 0) foreAft_[k] = d.at(k, fa);
                }
            }
        }
        if (!t_.empty()) current_ = 0;
    }
    onCursorChanged(controller_ ? controller_->cursor() : (t_.empty() ? 0.0 : t_.front()));
}

void StickFigureView::onCursorChanged(double t) {
    if (!t_.empty()) {
        const auto it = std::upper_bound(t_.begin(), t_.end(), t);
        current_ = it == t_.begin() ? 0 : (it - t_.begin()) - 1;
    }
    const Vec3 c = com();
    if (current_ < 0) {
        readout_->setText(tr("No body-com joint stream."));
    } else if (c.allFinite()) {
        const double fa = foreAft_.empty() ? kNaN : foreAft_[std::size_t(current_)];
        readout_->setText(tr("t = %1 s: CoM %2, %3, %4 mm from the lumbar joint (E, N, up); fore-aft %5 mm")
                              .arg(QString::number(t_[std::size_t(current_)], 'f', 2))
                              .arg(1e3 * c.x(), 0, 'f', 0)
                              .arg(1e3 * c.y(), 0, 'f', 0)
                              .arg(1e3 * c.z(), 0, 'f', 0)
                              .arg(std::isfinite(fa) ? QString::number(1e3 * fa, 'f', 0) : QStringLiteral("–")));
    } else {
        readout_->setText(tr("t = %1 s (no centre-of-mass stream beside the joints)")
                              .arg(QString::number(t_[std::size_t(current_)], 'f', 2)));
    }
    canvas_->update();
}

namespace {

QString trView(const char* text) { return QCoreApplication::translate("athlos::ui::StickFigureView", text); }

QDockWidget* makeDock(const Project* project, TimeController* time, const QString& stream, QWidget* parent) {
    auto* dock = new QDockWidget(trView("Stick figure"), parent);
    dock->setObjectName(QStringLiteral("stickFigureDock"));
    auto* view = new StickFigureView(project, dock);
    if (!stream.isEmpty()) (void)view->setStream(stream);  // a name from jointStreams(): cannot fail
    view->setTimeController(time);
    dock->setWidget(view);
    dock->setAttribute(Qt::WA_DeleteOnClose);
    return dock;
}

void launchStickFigure(Workspace& workspace) {
    if (!workspace.project()) return;
    QDockWidget* dock = makeDock(workspace.project(), workspace.timeController(), QString(), workspace.window());
    QObject::connect(workspace.notifier(), &WorkspaceNotifier::projectChanged, dock, &QWidget::close);
    workspace.addDock(dock, Qt::RightDockWidgetArea);
}

Status prepareStickFigureView(Workspace& workspace) {
    Project* project = workspace.project();
    const QStringList streams = project ? StickFigureView::jointStreams(*project) : QStringList();
    if (streams.isEmpty())
        return makeError(
            trView("no body-com result (kind joint-centres relative to the lumbar joint) in this project; "
                   "run body-model and body-com first"));
    // The CoM in the main time series, so the shared cursor is visible in both.
    const QString main = streams.front().chopped(7);
    workspace.selectItem(project->stream(main) ? main : streams.front());
    workspace.showTimeSeriesView();
    workspace.waitForPlots();
    TimeController* time = workspace.timeController();
    QDockWidget* dock = makeDock(project, time, streams.front(), workspace.window());
    workspace.addDock(dock, Qt::RightDockWidgetArea);
    workspace.resizeDock(dock, workspace.window()->width() * 2 / 5, Qt::Horizontal);
    const double b = time->begin(), e = time->end();
    time->setCursor(b + 0.6 * (e - b));
    QCoreApplication::processEvents();
    workspace.waitForPlots();
    return {};
}

}  // namespace

ATHLOS_REGISTER_TOOL({QStringLiteral("stick-figure-view"), QT_TRANSLATE_NOOP("Tools", "Stick figure (centre of mass)…"),
                      QT_TRANSLATE_NOOP("Tools", "Inertial"), launchStickFigure});
ATHLOS_REGISTER_VIEW({QStringLiteral("stick-figure"), prepareStickFigureView});

}  // namespace athlos::ui
