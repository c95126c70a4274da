// Writes that fail half-way: every image format writeImage() supports, written over an existing file
// onto a "full disk" (a child's file-size limit, and with root a real 64 KiB tmpfs), must fail with one
// line naming the file and the cause, keep the previous file byte-identical and leave no temporary.
// Also the staged-write primitive itself (base::AtomicFile, base::StagedPath).
#include "base/AtomicFile.hpp"
#include "render/imageio/ImageWriter.hpp"
#include "support/FillingDisk.hpp"
#include "support/TestFolder.hpp"

#include <OpenImageIO/imageio.h>
#include <cmath>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <sys/stat.h>

namespace speculum::render {
namespace {

namespace fs = std::filesystem;
using test::fileBytes;
using test::folderEntries;
using test::inChild;

const char* const kFormats[] = {".png", ".jpg", ".jpeg", ".tif", ".tiff", ".exr"};

// Noise compresses badly, so every format's file is far larger than the 4 KiB limit and the 64 KiB disk.
Image noisyFrame(int size, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> value(0.0f, 1.0f);
    Image image{size, size, std::vector<float>(static_cast<std::size_t>(size) * size * 4)};
    for (float& v : image.rgba) {
        v = value(random);
    }
    return image;
}

Image flat(int size, float v) {
    return Image{size, size, std::vector<float>(static_cast<std::size_t>(size) * size * 4, v)};
}

bool oneLine(const std::string& text) {
    return !text.empty() && text.find('\n') == std::string::npos && text.find('\r') == std::string::npos;
}

class WriteFailures : public ::testing::TestWithParam<const char*> {};

TEST_P(WriteFailures, FileSizeLimitKeepsThePreviousFileAndLeavesNoTemporary) {
    const fs::path folder = test::freshTestFolder();
    const fs::path target = folder / (std::string("out") + GetParam());
    ASSERT_TRUE(writeImage(target.string(), flat(8, 0.25f)).ok());
    const std::string before = fileBytes(target);
    ASSERT_FALSE(before.empty());

    const test::ChildOutcome child = inChild([&](std::string& text) {
        if (!test::limitFileSize(4096)) {
            return 3;
        }
        const base::Status written = writeImage(target.string(), noisyFrame(192, 1));
        text = written.ok() ? std::string("(succeeded)") : written.error();
        return written.ok() ? 1 : 0;
    });
    ASSERT_EQ(child.signal, 0) << "the writer died of signal " << child.signal << ": " << child.text;
    EXPECT_EQ(child.exitCode, 0) << "a write past the limit must fail: " << child.text;
    EXPECT_TRUE(oneLine(child.text)) << child.text;
    EXPECT_NE(child.text.find(target.filename().string()), std::string::npos) << child.text;
    EXPECT_NE(child.text.find("File too large"), std::string::npos) << child.text;
    EXPECT_NE(child.text.find("the previous file is unchanged"), std::string::npos) << child.text;
    EXPECT_EQ(fileBytes(target), before) << "the previous file must stay byte-identical";
    EXPECT_EQ(folderEntries(folder), std::vector<std::string>{target.filename().string()})
        << "no temporary may be left";
}

TEST_P(WriteFailures, FileSizeLimitWithNoPreviousFileLeavesNothing) {
    const fs::path folder = test::freshTestFolder();
    const fs::path target = folder / (std::string("new") + GetParam());
    const test::ChildOutcome child = inChild([&](std::string& text) {
        if (!test::limitFileSize(4096)) {
            return 3;
        }
        const base::Status written = writeImage(target.string(), noisyFrame(192, 2));
        text = written.ok() ? std::string("(succeeded)") : written.error();
        return written.ok() ? 1 : 0;
    });
    ASSERT_EQ(child.signal, 0) << child.text;
    EXPECT_EQ(child.exitCode, 0) << child.text;
    EXPECT_NE(child.text.find("nothing was written"), std::string::npos) << child.text;
    EXPECT_TRUE(folderEntries(folder).empty()) << "neither a partial file nor a temporary may be left";
}

// The real thing: a 64 KiB tmpfs that fills up (ENOSPC). Only root can mount one, in a private mount
// namespace, so the child checks the files itself (the parent cannot see that mount).
TEST_P(WriteFailures, SmallFullFileSystemKeepsThePreviousFile) {
    const fs::path folder = test::freshTestFolder();
    const std::string ext = GetParam();
    const test::ChildOutcome child = inChild([&](std::string& text) {
        if (std::string why = test::mountSmallFileSystem(folder, "64k"); !why.empty()) {
            text = why;
            return 77;
        }
        const fs::path target = folder / ("out" + ext);
        if (!writeImage(target.string(), flat(8, 0.5f)).ok()) {
            text = "could not write the first, small file";
            return 2;
        }
        const std::string before = fileBytes(target);
        const base::Status written = writeImage(target.string(), noisyFrame(256, 3));
        if (written.ok()) {
            text = "a 256x256 noise image fitted on a 64 KiB disk";
            return 1;
        }
        text = written.error();
        if (fileBytes(target) != before) {
            text += " [the previous file changed]";
            return 4;
        }
        if (folderEntries(folder) != std::vector<std::string>{target.filename().string()}) {
            text += " [a temporary was left]";
            return 5;
        }
        return 0;
    });
    if (child.exitCode == 77) {
        GTEST_SKIP() << "no small file system to fill: " << child.text;
    }
    ASSERT_EQ(child.signal, 0) << child.text;
    EXPECT_EQ(child.exitCode, 0) << child.text;
    EXPECT_TRUE(oneLine(child.text)) << child.text;
    EXPECT_NE(child.text.find("the disk is full (No space left on device)"), std::string::npos) << child.text;
    EXPECT_NE(child.text.find("the previous file is unchanged"), std::string::npos) << child.text;
}

INSTANTIATE_TEST_SUITE_P(EveryFormat, WriteFailures, ::testing::ValuesIn(kFormats),
                         [](const ::testing::TestParamInfo<const char*>& info) {
                             return std::string(info.param + 1);
                         });

TEST(WriteFailures, SrgbBytesOntoAFillingDiskFailToo) {
    const fs::path folder = test::freshTestFolder();
    const fs::path target = folder / "texture.png";
    TextureImage small{4, 4, std::vector<std::uint8_t>(64, 200), {}};
    ASSERT_TRUE(writeImage(target.string(), small).ok());
    const std::string before = fileBytes(target);
    const test::ChildOutcome child = inChild([&](std::string& text) {
        test::limitFileSize(4096);
        TextureImage big{160, 160, std::vector<std::uint8_t>(160 * 160 * 4), {}};
        std::mt19937 random(4);
        for (std::uint8_t& b : big.rgba8) {
            b = static_cast<std::uint8_t>(random());
        }
        const base::Status written = writeImage(target.string(), big);
        text = written.ok() ? std::string("(succeeded)") : written.error();
        return written.ok() ? 1 : 0;
    });
    EXPECT_EQ(child.exitCode, 0) << child.text;
    EXPECT_EQ(fileBytes(target), before);
    EXPECT_EQ(folderEntries(folder).size(), 1u);
}

// /dev/full-style targets: a device, or a FIFO, is never replaced (a rename would put a regular file in
// its place, which as root would break /dev/full for the whole machine) and never blocks.
TEST(WriteFailures, DeviceAndFifoTargetsAreRefusedAndLeftAlone) {
    struct stat st {};
    const fs::path folder = test::freshTestFolder();
    if (::stat("/dev/full", &st) == 0) {
        // An image name that leads to the device, through a link.
        const fs::path link = folder / "full.png";
        fs::create_symlink("/dev/full", link);
        const base::Status written = writeImage(link.string(), flat(4, 0.5f));
        ASSERT_FALSE(written.ok());
        EXPECT_NE(written.error().find("it is a device, not a regular file"), std::string::npos)
            << written.error();
        ASSERT_EQ(::stat("/dev/full", &st), 0);
        EXPECT_TRUE(S_ISCHR(st.st_mode)) << "/dev/full must still be a device";
        const base::Status raw = base::writeFileAtomically("/dev/full", "bytes");
        EXPECT_FALSE(raw.ok());
        ASSERT_EQ(::stat("/dev/full", &st), 0);
        EXPECT_TRUE(S_ISCHR(st.st_mode));
        fs::remove(link);
    }
    const fs::path fifo = folder / "pipe.png";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    const test::ChildOutcome child = inChild(
        [&](std::string& text) {
            const base::Status written = writeImage(fifo.string(), flat(4, 0.5f));
            text = written.ok() ? std::string("(succeeded)") : written.error();
            return written.ok() ? 1 : 0;
        },
        10);
    EXPECT_EQ(child.signal, 0) << "writing to a FIFO must not block (the alarm ended it)";
    EXPECT_EQ(child.exitCode, 0) << child.text;
    EXPECT_NE(child.text.find("FIFO"), std::string::npos) << child.text;
    ASSERT_EQ(::lstat(fifo.c_str(), &st), 0);
    EXPECT_TRUE(S_ISFIFO(st.st_mode));
    EXPECT_EQ(folderEntries(folder).size(), 1u);
}

// Files that belong together (a .gltf with its .bin and image) go in place as one set: when a rename fails
// after others were done (here the last file's temporary vanished first), the files already replaced are
// put back, the one that did not exist before is removed, and no temporary or backup stays.
TEST(CommitTogether, ARenameThatFailsHalfWayPutsBackEveryFileAlreadyReplaced) {
    const fs::path folder = test::freshTestFolder();
    const std::map<std::string, std::string> before = {{"set.bin", "old bin"}, {"set.gltf", "old gltf"}};
    for (const auto& [name, bytes] : before) {
        ASSERT_TRUE(base::writeFileAtomically((folder / name).string(), bytes).ok());
    }
    std::vector<base::AtomicFile> files;
    for (const char* name : {"set.bin", "set_0.png", "set.gltf"}) {
        base::Result<base::AtomicFile> file = base::AtomicFile::create((folder / name).string());
        ASSERT_TRUE(file.ok()) << file.error();
        ASSERT_TRUE(file->write(std::string("new ") + name).ok());
        ASSERT_TRUE(file->finish().ok());
        files.push_back(std::move(file).value());
    }
    ASSERT_EQ(::unlink(files.back().temporaryPath().c_str()), 0);

    const base::Status status = base::commitTogether(files);
    ASSERT_FALSE(status.ok());
    EXPECT_TRUE(oneLine(status.error())) << status.error();
    EXPECT_NE(status.error().find("set.gltf"), std::string::npos) << status.error();
    EXPECT_NE(status.error().find("the previous files are unchanged"), std::string::npos) << status.error();
    std::map<std::string, std::string> after;
    for (const std::string& name : folderEntries(folder)) {
        after[name] = fileBytes(folder / name);
    }
    EXPECT_EQ(after, before) << "the old set, whole, and nothing else";
}

TEST(CommitTogether, EveryFileOfTheSetIsReplaced) {
    const fs::path folder = test::freshTestFolder();
    ASSERT_TRUE(base::writeFileAtomically((folder / "set.gltf").string(), "old").ok());
    std::vector<base::AtomicFile> files;
    for (const char* name : {"set.bin", "set.gltf"}) {
        base::Result<base::AtomicFile> file = base::AtomicFile::create((folder / name).string());
        ASSERT_TRUE(file.ok()) << file.error();
        ASSERT_TRUE(file->write(std::string("new ") + name).ok());
        files.push_back(std::move(file).value());
    }
    ASSERT_TRUE(base::commitTogether(files).ok());
    const std::vector<std::string> names = folderEntries(folder);
    EXPECT_EQ(std::set<std::string>(names.begin(), names.end()),
              (std::set<std::string>{"set.bin", "set.gltf"}));
    EXPECT_EQ(fileBytes(folder / "set.gltf"), "new set.gltf");
}

// Half floats end at 65504: a tracer pixel of 1e6 used to become Inf in the EXR, a NaN stayed NaN.
TEST(ExrRange, OutOfRangeAndNanPixelsAreWrittenFinite) {
    const fs::path folder = test::freshTestFolder();
    const fs::path target = folder / "hot.exr";
    const float inf = std::numeric_limits<float>::infinity();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    Image image{4,
                1,
                {1e6f, 2.0f, 0.5f, 1.0f,  // over the half range
                 nan, nan, 0.25f, 1.0f,   // NaN colour
                 -1e6f, inf, -inf, 1.0f,  // negative over range and infinities
                 0.5f, 0.5f, 0.5f, nan}}; // NaN alpha
    ASSERT_TRUE(writeImage(target.string(), image).ok());

    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(target.string());
    ASSERT_TRUE(in);
    EXPECT_EQ(in->spec().format, OIIO::TypeDesc::HALF) << "still a half-float EXR";
    std::vector<float> back(16);
    ASSERT_TRUE(in->read_image(0, 0, 0, 4, OIIO::TypeDesc::FLOAT, back.data()));
    for (std::size_t i = 0; i < back.size(); ++i) {
        EXPECT_TRUE(std::isfinite(back[i])) << "channel value " << i << " is " << back[i];
    }
    EXPECT_FLOAT_EQ(back[0], 65504.0f);
    EXPECT_FLOAT_EQ(back[1], 2.0f);
    EXPECT_FLOAT_EQ(back[4], 0.0f);
    EXPECT_FLOAT_EQ(back[5], 0.0f);
    EXPECT_FLOAT_EQ(back[6], 0.25f);
    EXPECT_FLOAT_EQ(back[8], -65504.0f);
    EXPECT_FLOAT_EQ(back[9], 65504.0f);
    EXPECT_FLOAT_EQ(back[10], -65504.0f);
    EXPECT_FLOAT_EQ(back[15], 0.0f);
}

TEST(AtomicFile, CommitReplacesTheFileKeepingItsPermissions) {
    const fs::path folder = test::freshTestFolder();
    const fs::path target = folder / "a.txt";
    ASSERT_TRUE(base::writeFileAtomically(target.string(), "old").ok());
    ASSERT_EQ(::chmod(target.c_str(), 0640), 0);
    ASSERT_TRUE(base::writeFileAtomically(target.string(), "new contents").ok());
    EXPECT_EQ(fileBytes(target), "new contents");
    struct stat st {};
    ASSERT_EQ(::stat(target.c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 07777, 0640u);
    EXPECT_EQ(folderEntries(folder).size(), 1u);
}

TEST(AtomicFile, DestroyedWithoutCommitLeavesTheTargetAndNoTemporary) {
    const fs::path folder = test::freshTestFolder();
    const fs::path target = folder / "a.txt";
    ASSERT_TRUE(base::writeFileAtomically(target.string(), "old").ok());
    {
        base::Result<base::AtomicFile> file = base::AtomicFile::create(target.string());
        ASSERT_TRUE(file.ok()) << file.error();
        ASSERT_TRUE(file->write("half of it").ok());
        EXPECT_TRUE(fs::exists(file->temporaryPath()));
        EXPECT_EQ(fs::path(file->temporaryPath()).parent_path(), folder) << "staged in the same folder";
    }
    EXPECT_EQ(fileBytes(target), "old");
    EXPECT_EQ(folderEntries(folder).size(), 1u);
}

TEST(AtomicFile, TemporaryNamesAreUniqueAndKeepTheExtension) {
    const fs::path folder = test::freshTestFolder();
    base::Result<base::AtomicFile> a = base::AtomicFile::create((folder / "x.exr").string());
    base::Result<base::AtomicFile> b = base::AtomicFile::create((folder / "x.exr").string());
    ASSERT_TRUE(a.ok() && b.ok());
    EXPECT_NE(a->temporaryPath(), b->temporaryPath());
    EXPECT_EQ(fs::path(a->temporaryPath()).extension(), ".exr");
    EXPECT_EQ(fs::path(a->temporaryPath()).filename().string()[0], '.');
}

TEST(AtomicFile, ShortWritesUnderALimitAreAnError) {
    const fs::path folder = test::freshTestFolder();
    const fs::path target = folder / "big.bin";
    ASSERT_TRUE(base::writeFileAtomically(target.string(), "previous").ok());
    const test::ChildOutcome child = inChild([&](std::string& text) {
        test::limitFileSize(1000);
        const std::string bytes(5000, 'x'); // the first write() is cut short at 1000, the next fails
        const base::Status written = base::writeFileAtomically(target.string(), bytes);
        text = written.ok() ? std::string("(succeeded)") : written.error();
        return written.ok() ? 1 : 0;
    });
    EXPECT_EQ(child.exitCode, 0) << child.text;
    EXPECT_NE(child.text.find("big.bin: the file is larger than"), std::string::npos) << child.text;
    EXPECT_EQ(fileBytes(target), "previous");
    EXPECT_EQ(folderEntries(folder).size(), 1u);
}

TEST(AtomicFile, FollowsASymbolicLinkAndKeepsTheLink) {
    const fs::path folder = test::freshTestFolder();
    const fs::path real = folder / "real.txt";
    const fs::path link = folder / "link.txt";
    ASSERT_TRUE(base::writeFileAtomically(real.string(), "old").ok());
    fs::create_symlink("real.txt", link);
    ASSERT_TRUE(base::writeFileAtomically(link.string(), "new").ok());
    EXPECT_TRUE(fs::is_symlink(link));
    EXPECT_EQ(fileBytes(real), "new");
}

TEST(AtomicFile, UnwritableFolderIsOneLine) {
    const base::Status written = base::writeFileAtomically("/nonexistent-folder-speculum/x.txt", "bytes");
    ASSERT_FALSE(written.ok());
    EXPECT_EQ(written.error(),
              "/nonexistent-folder-speculum/x.txt: the folder does not exist (No such file or "
              "directory); nothing was written");
}

TEST(StagedPath, RefusesAWriterErrorOrAnEmptyFile) {
    const fs::path folder = test::freshTestFolder();
    const fs::path target = folder / "t.bin";
    ASSERT_TRUE(base::writeFileAtomically(target.string(), "old").ok());
    {
        base::Result<base::StagedPath> staged = base::StagedPath::create(target.string());
        ASSERT_TRUE(staged.ok());
        std::ofstream(staged->path()) << "partial";
        const base::Status s = staged->commit("write error at close");
        ASSERT_FALSE(s.ok());
        EXPECT_EQ(s.error(), target.string() + ": write error at close; the previous file is unchanged");
    }
    {
        base::Result<base::StagedPath> staged = base::StagedPath::create(target.string());
        ASSERT_TRUE(staged.ok());
        const base::Status s = staged->commit(); // the writer wrote nothing
        ASSERT_FALSE(s.ok());
        EXPECT_NE(s.error().find("empty file"), std::string::npos);
    }
    EXPECT_EQ(fileBytes(target), "old");
    EXPECT_EQ(folderEntries(folder).size(), 1u);
    base::Result<base::StagedPath> staged = base::StagedPath::create(target.string());
    ASSERT_TRUE(staged.ok());
    std::ofstream(staged->path()) << "complete";
    ASSERT_TRUE(staged->commit().ok());
    EXPECT_EQ(fileBytes(target), "complete");
    EXPECT_EQ(folderEntries(folder).size(), 1u);
}

} // namespace
} // namespace speculum::render
