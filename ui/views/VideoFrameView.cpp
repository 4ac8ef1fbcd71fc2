#include "ui/views/VideoFrameView.h"

#include <QPainter>

namespace athlos::ui {

VideoFrameView::VideoFrameView(QWidget* parent) : QWidget(parent) {
    setMinimumSize(160, 120);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
}

void VideoFrameView::setImage(const QImage& image) {
    image_ = image;
    text_.clear();
    update();
}

void VideoFrameView::setText(const QString& text) {
    image_ = {};
    text_ = text;
    update();
}

void VideoFrameView::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.fillRect(rect(), QColor(24, 24, 28));
    if (!image_.isNull()) {
        QSize size = image_.size().scaled(this->size(), Qt::KeepAspectRatio);
        const QRect target(QPoint((width() - size.width()) / 2, (height() - size.height()) / 2), size);
        painter.setRenderHint(QPainter::SmoothPixmapTransform);
        painter.drawImage(target, image_);
    } else {
        painter.setPen(QColor(200, 200, 200));
        painter.drawText(rect().adjusted(12, 12, -12, -12), Qt::AlignCenter | Qt::TextWordWrap, text_);
    }
}

}  // namespace athlos::ui
