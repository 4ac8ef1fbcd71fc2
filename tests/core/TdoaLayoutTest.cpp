#include "core/io/TdoaLayout.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace athlos;

TEST(TdoaLayout, GroupsLongRowsIntoInstantsWithNaNForMissingBeacons) {
    const std::vector<TdoaSample> samples = {
        {0.0, "B1", 1e-6, 2}, {0.0, "B2", 2e-6, 3}, {0.1, "B2", 3e-6, 4}, {0.1, "B3", 4e-6, 5}, {0.2, "B1", 5e-6, 6}};
    auto stream = tdoaStreamFromSamples(samples, "walk.csv");
    ASSERT_TRUE(stream.ok()) << stream.message().toStdString();
    const auto& info = stream->info();
    ASSERT_EQ(info.columns.size(), 3u);
    EXPECT_EQ(info.columns[0].name, "dt_B1");
    EXPECT_EQ(info.columns[2].unit, "s");
    auto data = stream->data();
    ASSERT_TRUE(data.ok());
    const StreamData& d = **data;
    ASSERT_EQ(d.rows(), 3u);
    EXPECT_EQ(d.t[1], 0.1);
    EXPECT_EQ(d.at(0, 0), 1e-6);
    EXPECT_TRUE(std::isnan(d.at(0, 2)));
    EXPECT_EQ(d.at(1, 2), 4e-6);
    EXPECT_TRUE(std::isnan(d.at(2, 1)));

    std::vector<TdoaSample> back;
    forEachTdoaSample(info, d, [&](double t, const QString& id, double dt) { back.push_back({t, id, dt, 0}); });
    ASSERT_EQ(back.size(), samples.size());
    for (std::size_t i = 0; i < back.size(); ++i) {
        EXPECT_EQ(back[i].t, samples[i].t);
        EXPECT_EQ(back[i].beacon, samples[i].beacon);
        EXPECT_EQ(back[i].dt, samples[i].dt);
    }
}

TEST(TdoaLayout, RejectsTimeGoingBackwardsNamingTheLine) {
    auto stream = tdoaStreamFromSamples({{0.2, "B1", 0, 2}, {0.1, "B1", 0, 3}}, "walk.csv");
    ASSERT_FALSE(stream.ok());
    EXPECT_TRUE(stream.message().contains("walk.csv:3")) << stream.message().toStdString();
}

TEST(TdoaLayout, RejectsDuplicateBeaconAtOneInstant) {
    auto stream = tdoaStreamFromSamples({{0.1, "B1", 0, 2}, {0.1, "B1", 0, 3}}, "walk.csv");
    ASSERT_FALSE(stream.ok());
    EXPECT_TRUE(stream.message().contains("walk.csv:3")) << stream.message().toStdString();
    EXPECT_TRUE(stream.message().contains("B1"));
}
