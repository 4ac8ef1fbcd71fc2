#pragma once
// The picture area of the video dock: the frame, scaled to fit with its aspect ratio on a dark
// background, or a placeholder text (no video, outside the video, a decode error).
#include <QImage>
#include <QString>
#include <QWidget>

namespace athlos::ui {

class VideoFrameView : public QWidget {
public:
    explicit VideoFrameView(QWidget* parent);

    void setImage(const QImage& image);
    void setText(const QString& text);
    QSize sizeHint() const override { return {480, 270}; }

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    QImage image_;
    QString text_;
};

}  // namespace athlos::ui
