// Beacon tables and the long TDoA stream as the CSV importer produces them (repeated t, numeric
// or text beacon ids), and the reference-node rule.
#include "plugins/lps/BeaconTable.h"
#include "plugins/lps/TdoaStream.h"

#include <QJsonArray>
#include <gtest/gtest.h>

using namespace athlos;
using namespace athlos::lps;

namespace {
Table beaconTable(const QStringList& ids) {
    Table t;
    t.kind = "beacons";
    TableColumn id{"id", "", true, {}, ids};
    TableColumn x{"x", "m", false, {}, {}}, y{"y", "m", false, {}, {}}, z{"z", "m", false, {}, {}};
    for (int i = 0; i < ids.size(); ++i) {
        x.numbers.push_back(10.0 * i);
        y.numbers.push_back(-5.0 * i);
        z.numbers.push_back(3.0 + i);
    }
    t.columns = {id, x, y, z};
    return t;
}
}  // namespace

TEST(BeaconTable, ReferenceRowAndAttributeRule) {
    auto plain = layoutFromTable(beaconTable({"1", "2", "3", "4"}), "g/beacons");
    ASSERT_TRUE(plain.ok());
    EXPECT_EQ(plain->size(), 4);
    EXPECT_TRUE(plain->reference.isZero());

    auto withRow = layoutFromTable(beaconTable({"1", "2", "Ref", "3", "4"}), "g/beacons");
    ASSERT_TRUE(withRow.ok());
    EXPECT_EQ(withRow->size(), 4);
    EXPECT_EQ(withRow->reference, Vector3(20, -10, 5));

    Table attr = beaconTable({"1", "2", "3", "4"});
    attr.attributes.insert("reference_node", QJsonArray{1.0, 2.0, 3.0});
    EXPECT_EQ(layoutFromTable(attr, "g/beacons")->reference, Vector3(1, 2, 3));

    EXPECT_FALSE(layoutFromTable(beaconTable({"1", "2", "3"}), "g/beacons").ok());  // < 4 beacons
    EXPECT_FALSE(layoutFromTable(beaconTable({"1", "2", "2", "4"}), "g/beacons").ok());
}

TEST(BeaconTable, RoundTripKeepsTheReferenceNode) {
    BeaconLayout layout;
    layout.ids = {"A", "B", "C", "D"};
    layout.positions = {Vector3(1, 2, 3), Vector3(4, 5, 6), Vector3(7, 8, 9), Vector3(1, 1, 1)};
    layout.reference = Vector3(0.5, 0, 0);
    auto back = layoutFromTable(tableFromLayout(layout), "x");
    ASSERT_TRUE(back.ok());
    EXPECT_EQ(back->ids, layout.ids);
    EXPECT_EQ(back->reference, layout.reference);
}

TEST(BeaconTable, IdMatching) {
    BeaconLayout layout;
    layout.ids = {"B01", "B02", "7", "x1", "y1"};
    EXPECT_EQ(matchBeaconId(layout, "B02"), 1);
    EXPECT_EQ(matchBeaconId(layout, "07"), 2);  // numeric value
    EXPECT_EQ(matchBeaconId(layout, "2"), 1);   // trailing number of B02
    EXPECT_EQ(matchBeaconId(layout, "1"), -1);  // ambiguous: B01, x1, y1
    EXPECT_EQ(matchBeaconId(layout, "Z"), -1);
}

TEST(TdoaStream, GroupsRepeatedTimesIntoEpochsWithNumericIds) {
    BeaconLayout layout;
    layout.ids = {"1", "2", "3", "4"};
    layout.positions.assign(4, Vector3::Zero());
    StreamInfo info;
    info.kind = "lps-tdoa";
    info.columns = {{"beacon", ""}, {"dt", "s"}};
    StreamData d(7, 2);
    const double rows[7][3] = {{0.0, 1, 1e-6}, {0.0, 2, 2e-6}, {0.0, 4, 3e-6}, {0.1, 3, 4e-6},
                               {0.1, 1, NAN},  {0.1, 2, 5e-6}, {0.2, 4, 6e-6}};
    for (int r = 0; r < 7; ++r) {
        d.t[size_t(r)] = rows[r][0];
        d.at(size_t(r), 0) = rows[r][1];
        d.at(size_t(r), 1) = rows[r][2];
    }
    const Stream stream(info, d);
    auto set = epochsFromStream(stream, d, layout, "w/tdoa");
    ASSERT_TRUE(set.ok()) << set.message().toStdString();
    ASSERT_EQ(set->epochs.size(), 3u);
    EXPECT_EQ(set->epochs[0].readings.size(), 3u);
    EXPECT_EQ(set->epochs[1].readings.size(), 2u);
    EXPECT_EQ(set->epochs[1].readings[0].beacon, 2);
    EXPECT_EQ(set->readingsSkipped, 1);
}

TEST(TdoaStream, TextIdsViaBeaconIdsAttributeAndUnknownIds) {
    BeaconLayout layout;
    layout.ids = {"B01", "B02", "B03", "B04"};
    layout.positions.assign(4, Vector3::Zero());
    std::vector<TdoaEpoch> epochs = {{0.0, {{2, 1e-6}, {0, 2e-6}}}, {0.5, {{1, 3e-6}, {3, 4e-6}}}};
    const Stream stream = streamFromEpochs(epochs, layout);
    EXPECT_EQ(stream.info().attributes.value("beacon_ids").toArray().size(), 4);
    auto data = stream.data();
    ASSERT_TRUE(data.ok());
    auto set = epochsFromStream(stream, **data, layout, "w/tdoa");
    ASSERT_TRUE(set.ok());
    ASSERT_EQ(set->epochs.size(), 2u);
    EXPECT_EQ(set->epochs[0].readings[0].beacon, 2);
    EXPECT_EQ(set->epochs[1].readings[1].beacon, 3);

    BeaconLayout other;
    other.ids = {"B01", "B02", "B03", "C9"};
    other.positions.assign(4, Vector3::Zero());
    auto missing = epochsFromStream(stream, **data, other, "w/tdoa");
    ASSERT_FALSE(missing.ok());
    EXPECT_TRUE(missing.message().contains("B04"));
}
