// bench --merge's checks and joining, on shard folders written here (results.json only): the shards join
// in the whole sweep's order, and a folder that is no shard's, shards of another count, a configuration
// two folders hold or none holds are refused with one line that names them.
#include "accuracy/ShardMerge.hpp"

#include <QTemporaryDir>
#include <filesystem>
#include <gtest/gtest.h>

namespace speculum::accuracy {
namespace {

namespace fs = std::filesystem;

const std::vector<std::string> kPlan = {"scene", "envmap-cube-64", "envmap-cube-128", "pcf-1", "pcf-5"};

Record record(const std::string& id) {
    Record r;
    r.config.id = id;
    r.config.family = id == "scene"             ? Family::Scene
                      : id.rfind("pcf", 0) == 0 ? Family::Shadows
                                                : Family::Envmap;
    r.config.reference =
        r.config.family == Family::Shadows ? ReferenceKind::HardShadows : ReferenceKind::Scene;
    r.config.label = id;
    r.cpuMs = 1.5;
    r.rmse = 0.01;
    r.psnr = 40.0 - static_cast<double>(id.size()) / 8.0; // distinct per record, exactly representable
    r.errorMap = "errors/" + id + ".png";
    return r;
}

// Writes DIR/results.json as `bench --shard K/N` does: the share's records and the shard's description.
fs::path writeShard(const QTemporaryDir& root, const std::string& name, base::Shard shard,
                    const std::string& host = "node-a", std::vector<std::string> plan = kPlan) {
    const fs::path folder = fs::path(root.path().toStdString()) / name;
    fs::create_directories(folder);
    RunInfo run;
    run.scene = "scene.speculum.json";
    run.sceneName = "scene.speculum.json";
    run.width = 64;
    run.height = 40;
    run.quick = true;
    run.renderer = "llvmpipe";
    run.shard = ShardInfo{shard, plan, "abc123", false, host};
    std::vector<Record> records;
    for (int i : base::shardItems(shard, static_cast<int>(plan.size()))) {
        records.push_back(record(plan[static_cast<std::size_t>(i)]));
        const ReferenceKind kind = records.back().config.reference;
        if (std::none_of(run.references.begin(), run.references.end(),
                         [&](const ReferenceInfo& r) { return r.kind == kind; }))
            run.references.push_back({kind, 100.0 + i, 2, "reference-" + referenceName(kind) + ".png"});
    }
    EXPECT_TRUE(writeJson((folder / "results.json").string(), run, records).ok());
    return folder;
}

TEST(ShardMerge, ShardsJoinInTheSweepsOrderSayingWhereEachRan) {
    QTemporaryDir root;
    const fs::path b = writeShard(root, "b", {1, 2, false}, "node-b");
    const fs::path a = writeShard(root, "a", {0, 2, false}, "node-a");
    auto merged = mergeShards({b, a});
    ASSERT_TRUE(merged.ok()) << merged.error();
    ASSERT_EQ(merged->records.size(), kPlan.size());
    for (std::size_t i = 0; i < kPlan.size(); ++i) {
        EXPECT_EQ(merged->records[i].config.id, kPlan[i]) << "the whole sweep's order";
        EXPECT_EQ(merged->records[i].psnr, record(kPlan[i]).psnr) << kPlan[i];
        ASSERT_TRUE(merged->records[i].ranOn.has_value()) << kPlan[i];
        EXPECT_EQ(merged->records[i].ranOn->shard, i % 2 == 0 ? "0/2" : "1/2") << kPlan[i];
        EXPECT_EQ(merged->records[i].ranOn->host, i % 2 == 0 ? "node-a" : "node-b") << kPlan[i];
        EXPECT_EQ(merged->recordFolder[i], i % 2 == 0 ? a : b) << kPlan[i];
    }
    ASSERT_EQ(merged->run.references.size(), 2u);
    EXPECT_EQ(merged->run.references[0].kind, ReferenceKind::Scene)
        << "in the order the sweep first needs them";
    EXPECT_EQ(merged->referenceFolder.at(ReferenceKind::HardShadows), b) << "pcf-1 is the first to need it";
    ASSERT_EQ(merged->run.shards.size(), 2u);
    EXPECT_EQ(merged->run.shards[0].shard, "0/2");
    EXPECT_EQ(merged->run.shards[1].configurations, 2u);
    EXPECT_TRUE(merged->run.timesFromSeveralMachines()) << "two hosts";
    EXPECT_FALSE(merged->run.shard.has_value()) << "the merged run is no shard";
}

TEST(ShardMerge, ContiguousShardsJoinToo) {
    QTemporaryDir root;
    auto merged = mergeShards({writeShard(root, "a", {0, 3, true}), writeShard(root, "b", {1, 3, true}),
                               writeShard(root, "c", {2, 3, true})});
    ASSERT_TRUE(merged.ok()) << merged.error();
    EXPECT_EQ(merged->records.size(), kPlan.size());
    EXPECT_FALSE(merged->run.timesFromSeveralMachines()) << "one host, one renderer";
}

void expectOneLine(const std::string& message) {
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

TEST(ShardMerge, AConfigurationInTwoFoldersIsNamedWithBoth) {
    QTemporaryDir root;
    const fs::path a = writeShard(root, "a", {0, 2, false}), again = writeShard(root, "again", {0, 2, false});
    auto merged = mergeShards({a, again, writeShard(root, "b", {1, 2, false})});
    ASSERT_FALSE(merged.ok());
    EXPECT_NE(merged.error().find("'scene' is in both"), std::string::npos) << merged.error();
    EXPECT_NE(merged.error().find(a.string()), std::string::npos) << merged.error();
    EXPECT_NE(merged.error().find(again.string()), std::string::npos) << merged.error();
    expectOneLine(merged.error());
}

TEST(ShardMerge, AConfigurationNoFolderHoldsNamesItsShard) {
    QTemporaryDir root;
    auto merged = mergeShards({writeShard(root, "a", {0, 3, false}), writeShard(root, "c", {2, 3, false})});
    ASSERT_FALSE(merged.ok());
    EXPECT_NE(merged.error().find("'envmap-cube-64' is in none of the folders: shard 1/3 measures it"),
              std::string::npos)
        << merged.error();
    expectOneLine(merged.error());
}

TEST(ShardMerge, ShardsOfAnotherRunAreRefused) {
    QTemporaryDir root;
    const fs::path a = writeShard(root, "a", {0, 2, false});
    auto count = mergeShards({a, writeShard(root, "b", {1, 3, false})});
    ASSERT_FALSE(count.ok());
    EXPECT_NE(count.error().find("shard 1/3, but"), std::string::npos) << count.error();
    expectOneLine(count.error());

    auto plan = mergeShards({a, writeShard(root, "p", {1, 2, false}, "node-a", {"scene", "pcf-1", "pcf-5"})});
    ASSERT_FALSE(plan.ok());
    EXPECT_NE(plan.error().find("another list of configurations"), std::string::npos) << plan.error();

    auto kind = mergeShards({a, writeShard(root, "k", {1, 2, true})});
    ASSERT_FALSE(kind.ok());
    EXPECT_NE(kind.error().find("contiguous"), std::string::npos) << kind.error();
}

TEST(ShardMerge, AFolderThatIsNoShardsIsRefused) {
    QTemporaryDir root;
    const fs::path empty = fs::path(root.path().toStdString()) / "empty";
    fs::create_directories(empty);
    auto none = mergeShards({empty});
    ASSERT_FALSE(none.ok());
    EXPECT_NE(none.error().find("not the output of a bench shard (no results.json)"), std::string::npos)
        << none.error();

    const fs::path whole = fs::path(root.path().toStdString()) / "whole";
    fs::create_directories(whole);
    RunInfo run;
    ASSERT_TRUE(writeJson((whole / "results.json").string(), run, {record("scene")}).ok());
    auto read = mergeShards({whole});
    ASSERT_FALSE(read.ok());
    EXPECT_NE(read.error().find("the output of a whole bench run, not of a shard"), std::string::npos)
        << read.error();
    expectOneLine(read.error());
}

TEST(ShardMerge, ARecordOutsideTheShardsShareIsRefused) {
    QTemporaryDir root;
    const fs::path a = writeShard(root, "a", {0, 2, false});
    RunInfo run;
    run.shard = ShardInfo{{0, 2, false}, kPlan, "abc123", false, "node-a"};
    ASSERT_TRUE(writeJson((a / "results.json").string(), run, {record("scene"), record("pcf-1")}).ok());
    auto read = readShardFolder(a);
    ASSERT_FALSE(read.ok());
    EXPECT_NE(read.error().find("'pcf-1', which is not in shard 0/2's share"), std::string::npos)
        << read.error();
}

} // namespace
} // namespace speculum::accuracy
