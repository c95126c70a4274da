// The bench's output folder is written all at once through a hidden staging folder; a run that was killed
// leaves that folder behind, and the next run into the same folder removes it.
#include "accuracy/StagedOutput.hpp"

#include <QTemporaryDir>
#include <fstream>
#include <gtest/gtest.h>
#include <unistd.h>

namespace speculum::accuracy {
namespace {

namespace fs = std::filesystem;

void writeFile(const fs::path& path, const char* text) {
    std::ofstream(path) << text;
}

TEST(BenchStaging, CommitMovesTheFilesInAndLeavesNoStagingFolder) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const fs::path folder = fs::path(dir.path().toStdString()) / "out";
    auto staged = StagedOutput::begin(folder);
    ASSERT_TRUE(staged.ok()) << staged.error();
    writeFile(staged->staging() / "results.csv", "a,b\n");
    ASSERT_TRUE(staged->commit().ok());
    EXPECT_TRUE(fs::exists(folder / "results.csv"));
    for (const fs::directory_entry& entry : fs::directory_iterator(folder))
        EXPECT_NE(entry.path().filename().string().rfind(".speculum-bench-", 0), 0u) << entry.path();
}

TEST(BenchStaging, TheNextRunRemovesTheStagingFolderOfAKilledRunButNotOfALiveOne) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const fs::path folder(dir.path().toStdString());
    // No process has this id (above any pid_max Linux allows), so its run is over.
    const fs::path abandoned = folder / ".speculum-bench-999999999.partial";
    fs::create_directory(abandoned);
    writeFile(abandoned / "results.csv", "half-written");
    // The parent process (the test runner) is alive: its folder may be a run in progress.
    const fs::path live = folder / (".speculum-bench-" + std::to_string(::getppid()) + ".partial");
    fs::create_directory(live);
    // Not ours, whatever it looks like.
    const fs::path userFolder = folder / ".speculum-bench-notes.partial";
    fs::create_directory(userFolder);
    writeFile(folder / "keep.txt", "the user's");

    auto staged = StagedOutput::begin(folder);
    ASSERT_TRUE(staged.ok()) << staged.error();
    EXPECT_FALSE(fs::exists(abandoned));
    EXPECT_TRUE(fs::exists(live));
    EXPECT_TRUE(fs::exists(userFolder));
    EXPECT_TRUE(fs::exists(folder / "keep.txt"));
    ASSERT_TRUE(staged->commit().ok());
    EXPECT_TRUE(fs::exists(live)) << "another run's folder is never touched";
}

} // namespace
} // namespace speculum::accuracy
