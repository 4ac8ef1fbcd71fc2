// Rolling 4-week baselines and flags of an athlete's sessions (SessionHistory), hand-computed.
#include "core/model/SessionHistory.h"

#include <gtest/gtest.h>
#include <cmath>

using namespace athlos;

namespace {
SessionRecord session(const QString& athlete, int day, double distance, double sprints) {
    SessionRecord r;
    r.athlete = athlete;
    r.session = QStringLiteral("%1 day %2").arg(athlete).arg(day);
    r.date = QDateTime(QDate(2026, 10, 1), QTime(10, 0), Qt::UTC).addDays(day);
    r.values = {{QStringLiteral("distance"), distance}, {QStringLiteral("sprint_count"), sprints}};
    return r;
}
}  // namespace

TEST(SessionHistory, RollingBaselineRatiosAndFlags) {
    SessionHistory::Params p;
    p.metrics = {QStringLiteral("distance"), QStringLiteral("sprint_count")};
    // Anna: days 0, 7, 14 at 5000 m; day 21 at 8000 m (ratio 1.6: high); day 60 alone in its window.
    // Ben: day 3 then day 10 with fewer sprints (4 vs 10: 0.4, low).
    std::vector<SessionRecord> records{
        session(QStringLiteral("Anna"), 21, 8000, 10), session(QStringLiteral("Ben"), 10, 5000, 4),
        session(QStringLiteral("Anna"), 0, 5000, 10),  session(QStringLiteral("Anna"), 7, 5000, 10),
        session(QStringLiteral("Anna"), 14, 5000, 10), session(QStringLiteral("Ben"), 3, 5000, 10),
        session(QStringLiteral("Anna"), 60, 6000, 10)};
    auto t = SessionHistory::build(records, p);
    ASSERT_TRUE(t.ok()) << t.message().toStdString();
    const auto& athletes = t->column(QStringLiteral("athlete"))->texts;
    ASSERT_EQ(athletes, (QStringList{QStringLiteral("Anna"), QStringLiteral("Anna"), QStringLiteral("Anna"),
                                     QStringLiteral("Anna"), QStringLiteral("Anna"), QStringLiteral("Ben"),
                                     QStringLiteral("Ben")}));
    const auto& baseline = t->column(QStringLiteral("distance_baseline"))->numbers;
    const auto& ratio = t->column(QStringLiteral("distance_ratio"))->numbers;
    EXPECT_TRUE(std::isnan(baseline[0]));  // first session: no baseline
    EXPECT_DOUBLE_EQ(baseline[3], 5000.0);
    EXPECT_DOUBLE_EQ(ratio[3], 1.6);
    EXPECT_TRUE(std::isnan(baseline[4]));  // day 60: the latest earlier session (day 21) is 39 days before
    const auto& flags = t->column(QStringLiteral("flags"))->texts;
    EXPECT_EQ(flags[3], QStringLiteral("distance high"));
    EXPECT_EQ(flags[6], QStringLiteral("sprint_count low"));
    EXPECT_EQ(flags[1], QString());
}

TEST(SessionHistory, UnknownMetricIsAnError) {
    SessionHistory::Params p;
    p.metrics = {QStringLiteral("tackles")};
    EXPECT_FALSE(SessionHistory::build({session(QStringLiteral("Anna"), 0, 5000, 10)}, p).ok());
}
