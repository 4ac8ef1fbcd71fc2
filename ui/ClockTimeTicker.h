#pragma once
// Time axis labels as clock time: the plot's key is a stream's t (s since its first sample), the
// labels are t0 + t as a UTC time of day (hh:mm:ss, with the date when the range spans days), and
// the ticks fall on round clock times (whole seconds, minutes, ...), not on round values of t.
// t0 comes from the stream's attributes: t0_utc (an instant) or t0_time_of_day (a clock time
// without a date); see core/io/TimeFormats.h.
#include <QJsonObject>
#include <optional>
#include <qcustomplot.h>

namespace athlos::ui {

class ClockTimeTicker : public QCPAxisTickerDateTime {
public:
    // t0: seconds since the Unix epoch (or since midnight for a time of day) of t = 0.
    explicit ClockTimeTicker(double t0);

    // t0 of a stream from its attributes, or nothing when the file gave no absolute time.
    static std::optional<double> t0Of(const QJsonObject& attributes);

    double t0() const { return t0_; }

protected:
    QString getTickLabel(double tick, const QLocale& locale, QChar formatChar, int precision) override;
    QVector<double> createTickVector(double tickStep, const QCPRange& range) override;

private:
    double t0_;
    double step_ = 1.0;  // of the ticks being labelled
};

}  // namespace athlos::ui
