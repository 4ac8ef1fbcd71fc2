// The representative subsample of noise=auto: evenly spread chunks, or the whole input when short.
#include "plugins/positioning/PositionFilter.h"

#include <gtest/gtest.h>

using namespace athlos::positioning;

TEST(PositionFilter, NoiseChunksSpreadOverTheRecording) {
    PositionSamples fixes;
    for (int k = 0; k < 6000; ++k) {
        fixes.t.push_back(k * 0.1);
        fixes.p.emplace_back(k, 0);
    }
    const auto chunks = PositionFilter::noiseChunks(fixes, 30.0, 4);
    ASSERT_EQ(chunks.size(), 4u);
    EXPECT_NEAR(chunks.front().t.front(), 0.0, 1e-9);
    EXPECT_NEAR(chunks.back().t.back(), 599.9, 0.1);
    for (const auto& c : chunks) EXPECT_NEAR(c.t.back() - c.t.front(), 30.0, 0.11);
    EXPECT_EQ(PositionFilter::noiseChunks(fixes, 300.0, 4).size(), 1u);  // shorter than 4 × 300 s: the whole input
}
