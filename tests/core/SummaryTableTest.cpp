// SummaryTable (athlos batch --summary): rows stacked in order with project and recording, the union
// of the columns, NaN/empty where a table lacks a column, and a unit clash refused with its place.
#include "core/model/SummaryTable.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace athlos;

namespace {

TableColumn numbers(const char* name, const char* unit, std::vector<double> v) {
    return {QString::fromLatin1(name), QString::fromLatin1(unit), false, std::move(v), {}};
}
TableColumn texts(const char* name, QStringList v) { return {QString::fromLatin1(name), {}, true, {}, std::move(v)}; }

}  // namespace

TEST(SummaryTable, StacksRowsWithTheUnionOfColumns) {
    Table a;
    a.columns = {texts("period", {"whole", "first"}), numbers("distance", "m", {5000, 2400})};
    Table b;
    b.columns = {texts("period", {"whole"}), numbers("max_speed", "m/s", {8.5}), numbers("distance", "m", {4100})};
    SummaryTable s;
    ASSERT_TRUE(s.add(QStringLiteral("p1.athlos"), QStringLiteral("match"), a).ok());
    ASSERT_TRUE(s.add(QStringLiteral("p2.athlos"), QStringLiteral("training"), b).ok());
    const Table& t = s.table();
    EXPECT_EQ(s.sources(), 2);
    ASSERT_EQ(t.rows(), 3);
    ASSERT_EQ(t.columns.size(), 5u);
    EXPECT_EQ(t.columns[0].name, QStringLiteral("project"));
    EXPECT_EQ(t.columns[1].name, QStringLiteral("recording"));
    EXPECT_EQ(t.columns[2].name, QStringLiteral("period"));
    EXPECT_EQ(t.columns[3].name, QStringLiteral("distance"));
    EXPECT_EQ(t.columns[4].name, QStringLiteral("max_speed"));
    EXPECT_EQ(t.columns[0].texts, (QStringList{"p1.athlos", "p1.athlos", "p2.athlos"}));
    EXPECT_EQ(t.columns[1].texts, (QStringList{"match", "match", "training"}));
    EXPECT_EQ(t.columns[2].texts, (QStringList{"whole", "first", "whole"}));
    EXPECT_EQ(t.columns[3].numbers, (std::vector<double>{5000, 2400, 4100}));
    EXPECT_EQ(t.columns[3].unit, QStringLiteral("m"));
    EXPECT_TRUE(std::isnan(t.columns[4].numbers[0]));
    EXPECT_TRUE(std::isnan(t.columns[4].numbers[1]));
    EXPECT_EQ(t.columns[4].numbers[2], 8.5);
    for (const auto& c : t.columns) EXPECT_EQ(c.size(), 3);
}

TEST(SummaryTable, RefusesAColumnWithAnotherUnit) {
    Table a;
    a.columns = {numbers("distance", "m", {5000})};
    Table b;
    b.name = QStringLiteral("metrics");
    b.columns = {numbers("distance", "km", {5})};
    SummaryTable s;
    ASSERT_TRUE(s.add(QStringLiteral("p1"), QStringLiteral("r"), a).ok());
    const Status st = s.add(QStringLiteral("p2"), QStringLiteral("r2"), b);
    ASSERT_FALSE(st.ok());
    EXPECT_TRUE(st.message().contains(QStringLiteral("p2"))) << qPrintable(st.message());
    EXPECT_TRUE(st.message().contains(QStringLiteral("'distance'"))) << qPrintable(st.message());
    EXPECT_EQ(s.table().rows(), 1);  // nothing of the refused table was added
}
