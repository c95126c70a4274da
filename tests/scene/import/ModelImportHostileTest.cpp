// Hostile model files: node graphs that unfold into billions of nodes,
// cycles, nesting deep enough to overflow a recursive reader's stack, headers that declare absurd
// counts under a misleading name, and FIFOs or devices as the model or as a file it references. Each
// must be refused within seconds with one line naming the cause. Every import runs in a child process
// under a time and address-space limit, so a regression fails the test instead of hanging or swapping CI;
// the child's time and peak RSS are printed for each file.
#include "scene/import/ModelImport.hpp"
#include "scene/import/ModelPrecheck.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iostream>
#include <poll.h>
#include <sstream>
#include <string>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#if defined(__SANITIZE_ADDRESS__)
#define SPECULUM_TEST_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SPECULUM_TEST_ASAN 1
#endif
#endif

namespace speculum::document {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr int kLimitSeconds = 20;

struct Outcome {
    bool finished = false; // the child reported (imported or refused)
    bool imported = false;
    std::string message; // the refusal, or how the child died
    double seconds = 0.0;
    long peakKb = 0; // the child's peak resident set
};

// Imports `file` in a child process (alarm and a 4 GB address-space limit) and reads back its answer.
Outcome importInChild(const fs::path& file) {
    Outcome outcome;
    int fds[2];
    if (::pipe(fds) != 0) {
        outcome.message = std::string("pipe: ") + std::strerror(errno);
        return outcome;
    }
    std::fflush(nullptr);
    const auto start = Clock::now();
    const pid_t pid = ::fork();
    if (pid == 0) {
        ::close(fds[0]);
        const rlimit noCore{0, 0};
        ::setrlimit(RLIMIT_CORE, &noCore);
#if !defined(SPECULUM_TEST_ASAN)
        // AddressSanitizer has terabytes of shadow memory mapped already: under an address-space limit its
        // next mapping fails and it aborts. Its builds rely on the alarm and on the peak asserted below.
        const rlimit memory{rlim_t(4) << 30, rlim_t(4) << 30};
        ::setrlimit(RLIMIT_AS, &memory);
#endif
        ::alarm(kLimitSeconds);
        std::vector<std::string> warnings;
        const auto model = scene::importModelFile(file.string(), warnings);
        // The reader runs in a process of its own (ModelImportProcess): its peak, reaped by now, is this
        // process's largest child's.
        rusage reader{};
        ::getrusage(RUSAGE_CHILDREN, &reader);
        std::string report =
            std::to_string(reader.ru_maxrss) + " " + (model ? std::string("I") : "R" + model.error());
        report.resize(std::min<std::size_t>(report.size(), PIPE_BUF));
        const ssize_t written = ::write(fds[1], report.data(), report.size());
        ::_exit(written == ssize_t(report.size()) ? 0 : 3);
    }
    ::close(fds[1]);
    std::string report;
    const auto deadline = start + std::chrono::seconds(kLimitSeconds + 5);
    for (;;) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
        pollfd p{fds[0], POLLIN, 0};
        if (left.count() <= 0 || ::poll(&p, 1, int(left.count())) == 0) {
            ::kill(pid, SIGKILL);
            break;
        }
        char buffer[PIPE_BUF];
        const ssize_t n = ::read(fds[0], buffer, sizeof buffer);
        if (n > 0) {
            report.append(buffer, std::size_t(n));
        } else if (n == 0 || errno != EINTR) {
            break;
        }
    }
    ::close(fds[0]);
    int status = 0;
    rusage usage{};
    ::wait4(pid, &status, 0, &usage);
    outcome.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    outcome.peakKb = usage.ru_maxrss;
    if (WIFSIGNALED(status)) {
        outcome.message = std::string("killed by ") + strsignal(WTERMSIG(status));
    } else if (report.empty()) {
        outcome.message = "exited with status " + std::to_string(WEXITSTATUS(status));
    } else {
        // "<reader's peak kB> I" or "<reader's peak kB> R<message>"
        const std::size_t space = report.find(' ');
        if (space != std::string::npos && space + 1 < report.size()) {
            outcome.peakKb = std::max(outcome.peakKb, std::atol(report.substr(0, space).c_str()));
            report.erase(0, space + 1);
        }
        outcome.finished = true;
        outcome.imported = report[0] == 'I';
        outcome.message = report.substr(1);
    }
    return outcome;
}

class HostileModels : public ::testing::Test {
protected:
    void SetUp() override {
        m_dir = fs::temp_directory_path() / ("speculum-hostile-" + std::to_string(::getpid()) + "-" +
                                             ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(m_dir);
        fs::create_directories(m_dir);
    }
    void TearDown() override { fs::remove_all(m_dir); }

    fs::path write(const std::string& name, const std::string& content) {
        const fs::path path = m_dir / name;
        std::ofstream(path, std::ios::binary) << content;
        return path;
    }
    fs::path fifo(const std::string& name) {
        const fs::path path = m_dir / name;
        EXPECT_EQ(::mkfifo(path.c_str(), 0600), 0) << std::strerror(errno);
        return path;
    }

    // Refused within a few seconds, with one line that names the file and contains `cause`.
    void expectRefused(const fs::path& file, const std::string& cause) {
        const Outcome outcome = importInChild(file);
        std::cout << "[ figures  ] " << file.filename().string() << ": " << outcome.seconds << " s, peak RSS "
                  << outcome.peakKb / 1024 << " MB: " << outcome.message << "\n";
        ASSERT_TRUE(outcome.finished) << file.filename() << ": " << outcome.message;
        EXPECT_FALSE(outcome.imported) << file.filename();
        EXPECT_NE(outcome.message.find(file.filename().string() + ": "), std::string::npos)
            << outcome.message;
        EXPECT_NE(outcome.message.find(cause), std::string::npos) << outcome.message;
        EXPECT_EQ(outcome.message.find('\n'), std::string::npos) << outcome.message;
        EXPECT_LT(outcome.seconds, 5.0) << outcome.message;
        EXPECT_LT(outcome.peakKb, 512 * 1024) << outcome.message;
    }

    fs::path m_dir;
};

// One triangle: three float positions, as base64 for a data URI.
const std::string kTriangleBase64 = "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA";

std::string triangleBytes() {
    const float p[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    return std::string(reinterpret_cast<const char*>(p), sizeof p);
}

// A glTF with the given nodes array, scene 0 rooted at node 0, one triangle mesh from `bufferUri` (none:
// the .glb's BIN chunk).
std::string gltf(const std::string& nodes, const std::string& bufferUri) {
    return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":)" + nodes +
           R"(,"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)"
           R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3",)"
           R"("min":[0,0,0],"max":[1,1,0]}],"bufferViews":[{"buffer":0,"byteLength":36}],)"
           R"("buffers":[{"byteLength":36)" +
           (bufferUri.empty() ? std::string() : ",\"uri\":\"" + bufferUri + "\"") + "}]}";
}

std::string dataUri() {
    return "data:application/octet-stream;base64," + kTriangleBase64;
}

// Node i lists node i+1 twice: 2^levels instances once unfolded.
std::string dagNodes(int levels) {
    std::string nodes = "[";
    for (int i = 0; i < levels; ++i) {
        nodes += "{\"children\":[" + std::to_string(i + 1) + "," + std::to_string(i + 1) + "]},";
    }
    return nodes + "{\"mesh\":0}]";
}

std::string chainNodes(int length) {
    std::string nodes = "[";
    for (int i = 0; i + 1 < length; ++i) {
        nodes += "{\"children\":[" + std::to_string(i + 1) + "]},";
    }
    return nodes + "{\"mesh\":0}]";
}

std::string glb(std::string json, const std::string& bin) {
    while (json.size() % 4 != 0) {
        json += ' ';
    }
    const auto u32 = [](std::uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
    std::string chunks = u32(std::uint32_t(json.size())) + "JSON" + json;
    if (!bin.empty()) {
        chunks += u32(std::uint32_t(bin.size())) + std::string("BIN\0", 4) + bin;
    }
    return "glTF" + u32(2) + u32(std::uint32_t(12 + chunks.size())) + chunks;
}

std::string colladaHeader() {
    return R"(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
<asset><unit name="meter" meter="1"/><up_axis>Y_UP</up_axis></asset>
)";
}

TEST_F(HostileModels, GltfDagIsRefusedWithoutUnfolding) {
    expectRefused(
        write("dag.gltf", gltf(dagNodes(40), dataUri())),
        "the node graph unfolds into more than 100000 node instances (nodes[40] is reached 2^40 ways)");
}

TEST_F(HostileModels, GlbDagIsRefused) {
    expectRefused(write("dag.glb", glb(gltf(dagNodes(40), dataUri()), {})), "2^40 ways");
}

TEST_F(HostileModels, ColladaInstanceNodeDagIsRefused) {
    std::string dae = colladaHeader() + "<library_nodes>\n";
    for (int i = 0; i < 40; ++i) {
        dae += "<node id=\"n" + std::to_string(i) + "\"><instance_node url=\"#n" + std::to_string(i + 1) +
               "\"/><instance_node url=\"#n" + std::to_string(i + 1) + "\"/></node>\n";
    }
    dae += "<node id=\"n40\"/></library_nodes>\n<library_visual_scenes><visual_scene id=\"s\">"
           "<node id=\"top\"><instance_node url=\"#n0\"/></node></visual_scene></library_visual_scenes>\n"
           "<scene><instance_visual_scene url=\"#s\"/></scene></COLLADA>\n";
    expectRefused(write("dag.dae", dae), "node 'n40' is reached 2^40 ways");
}

TEST_F(HostileModels, ColladaInstanceNodeCycleIsRefused) {
    const std::string dae =
        colladaHeader() +
        "<library_nodes><node id=\"a\"><instance_node url=\"#b\"/></node><node id=\"b\"><instance_node "
        "url=\"#a\"/></node></library_nodes><library_visual_scenes><visual_scene id=\"s\"><node "
        "id=\"top\"><instance_node url=\"#a\"/></node></visual_scene></library_visual_scenes><scene>"
        "<instance_visual_scene url=\"#s\"/></scene></COLLADA>\n";
    expectRefused(write("cycle.dae", dae), "the node graph has a cycle");
}

TEST_F(HostileModels, GltfCycleIsRefused) {
    expectRefused(write("cycle.gltf", gltf(R"([{"children":[1]},{"children":[0],"mesh":0}])", dataUri())),
                  "the node graph has a cycle (nodes[0] is its own descendant)");
}

// Qt's JSON keeps the last of two equal keys, Assimp's the first: a hostile graph followed by a benign
// one (also spelled with an escape) must not pass as the benign one.
TEST_F(HostileModels, GltfWithTheNodesKeyTwiceIsRefused) {
    std::string twice = gltf(dagNodes(40), dataUri());
    twice.insert(twice.size() - 1, R"(,"nodes":[{"mesh":0}])");
    expectRefused(write("twice.gltf", twice), "the glTF JSON has the key 'nodes' twice in one object");
    std::string escaped = gltf(dagNodes(40), dataUri());
    escaped.insert(escaped.size() - 1, R"(,"nod\u0065s":[{"mesh":0}])");
    expectRefused(write("escaped.gltf", escaped), "the key 'nodes' twice");
}

TEST_F(HostileModels, DeepGltfChainIsRefusedBeforeAssimp) {
    expectRefused(write("chain.gltf", gltf(chainNodes(100000), dataUri())),
                  "the node hierarchy is deeper than 1024 levels");
}

TEST_F(HostileModels, DeepColladaNestingIsRefused) {
    std::string dae = colladaHeader() + "<library_visual_scenes><visual_scene id=\"s\">";
    for (int i = 0; i < 100000; ++i) {
        dae += "<node>";
    }
    for (int i = 0; i < 100000; ++i) {
        dae += "</node>";
    }
    dae += "</visual_scene></library_visual_scenes></COLLADA>\n";
    expectRefused(write("deep.dae", dae), "XML elements nested deeper than 1024 levels");
}

TEST_F(HostileModels, DeepAsciiFbxAndXNestingAreRefused) {
    std::string fbx = "; FBX 7.4.0 project file\nFBXHeaderExtension:  {\n FBXVersion: 7400\n}\nObjects:  {\n";
    std::string x = "xof 0303txt 0032\n";
    for (int i = 0; i < 100000; ++i) {
        fbx += "Model: \"m\" {\n";
        x += "Frame f {\n";
    }
    expectRefused(write("deep.fbx", fbx), "nested deeper than 1024 levels");
    expectRefused(write("deep.x", x), "nested deeper than 1024 levels");
}

TEST_F(HostileModels, DeepBinaryFbxRecordsAreRefused) {
    constexpr int kDepth = 5000;
    std::string fbx("Kaydara FBX Binary  \0\x1a\0", 23);
    const std::uint32_t version = 7400;
    fbx.append(reinterpret_cast<const char*>(&version), 4);
    const std::uint32_t total = 27 + 2 * 13 * kDepth;
    for (int k = 0; k < kDepth; ++k) {
        const std::uint32_t header[3] = {total - 13u * k, 0, 0}; // end offset, properties, their bytes
        fbx.append(reinterpret_cast<const char*>(header), 12);
        fbx += '\0'; // no name
    }
    fbx += std::string(13 * kDepth, '\0'); // the null records closing each list
    expectRefused(write("deep-binary.fbx", fbx), "FBX records nested deeper than 1024 levels");
}

TEST_F(HostileModels, OffWithBogusCountsIsRefusedWhateverItsName) {
    const std::string off = "OFF\n999999999999 999999999999 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    expectRefused(write("bogus.obj", off), "declares 999999999999 elements");
    expectRefused(write("bogus", off), "declares 999999999999 elements");
    expectRefused(write("bogus.xyz", "# comment\noff 999999999999 1 0\n"), "declares 999999999999 elements");
    // Found by fuzz_model_import: the count glued to the keyword, too long to fit (an 11 GB allocation).
    expectRefused(write("glued.off", "OFF" + std::string(100, '8') + "\n3 1 0\n0 0 0\n"),
                  "invalid element count");
    expectRefused(write("glued2.off", "OFF999999999999 1 0\n0 0 0\n"), "declares 999999999999 elements");
}

TEST_F(HostileModels, PlyWithBogusCountIsRefused) {
    expectRefused(write("bogus.stl", "ply\nformat ascii 1.0\nelement vertex 4000000000\nproperty float x\n"
                                     "property float y\nproperty float z\nend_header\n0 0 0\n"),
                  "declares 4000000000 elements");
}

// Found by fuzz_model_import: Assimp's PLY reader never returns on a header without end_header.
TEST_F(HostileModels, PlyWithoutEndOfHeaderIsRefused) {
    expectRefused(write("unended.ply",
                        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                        "property float y\nproperty float z\nenc_header\n0 0 0\n1 0 0\n0 1 0\n"),
                  "the PLY header has no end_header line");
    expectRefused(write("garbled.ply", "ply\nformat ascii 1\xa0\n<blendervertex 3\nproperty float x\n"
                                       "end_header\n0 0 0\n"),
                  "the PLY header line 4 is not understood: 'property float x'");
}

TEST_F(HostileModels, FifoAsTheModelIsRefused) {
    expectRefused(fifo("model.obj"), "it is a FIFO (named pipe), not a regular file");
    const fs::path link = m_dir / "link.gltf";
    fs::create_symlink(m_dir / "model.obj", link);
    expectRefused(link, "it is a FIFO (named pipe), not a regular file");
}

TEST_F(HostileModels, FifoAsAGltfBufferIsRefusedNamingIt) {
    fifo("data.bin");
    expectRefused(write("scene.gltf", gltf("[{\"mesh\":0}]", "data.bin")),
                  "referenced file 'data.bin': it is a FIFO (named pipe), not a regular file");
}

TEST_F(HostileModels, DeviceAsAGltfBufferIsRefused) {
    fs::create_symlink("/dev/zero", m_dir / "zero.bin");
    expectRefused(write("zero.gltf", gltf("[{\"mesh\":0}]", "zero.bin")),
                  "referenced file 'zero.bin': it is a device, not a regular file");
}

TEST_F(HostileModels, FifoAsAnObjMaterialLibraryIsRefused) {
    fifo("materials.mtl");
    expectRefused(write("model.obj", "mtllib materials.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"),
                  "referenced file 'materials.mtl': it is a FIFO");
}

// The checks must not cost ordinary files anything: the same glTF with a regular buffer file (through
// the IO system), a small DAG under the limit and a moderately deep chain still import.
TEST_F(HostileModels, OrdinaryFilesStillImport) {
    write("data.bin", triangleBytes());
    for (const fs::path& file : {write("external.gltf", gltf("[{\"mesh\":0}]", "data.bin")),
                                 write("small-dag.gltf", gltf(dagNodes(10), dataUri())),
                                 write("chain.gltf", gltf(chainNodes(500), dataUri())),
                                 write("binary.glb", glb(gltf("[{\"mesh\":0}]", ""), triangleBytes()))}) {
        const Outcome outcome = importInChild(file);
        EXPECT_TRUE(outcome.finished && outcome.imported) << file.filename() << ": " << outcome.message;
    }
}

TEST(ModelPrecheck, IdentifiesByContent) {
    using scene::detail::ModelContent;
    const auto kind = [](const std::string& bytes) {
        return scene::detail::identifyModelContent(bytes.data(), bytes.size());
    };
    EXPECT_EQ(kind("glTF\x02"), ModelContent::Glb);
    EXPECT_EQ(kind("\xEF\xBB\xBF  {\"asset\":{}}"), ModelContent::GltfJson);
    EXPECT_EQ(kind("<?xml version=\"1.0\"?><COLLADA/>"), ModelContent::Xml);
    EXPECT_EQ(kind("# made by hand\nCOFF\n3 1 0\n"), ModelContent::Off);
    EXPECT_EQ(kind("ply\nformat ascii 1.0\n"), ModelContent::Ply);
    EXPECT_EQ(kind(std::string("Kaydara FBX Binary  \0", 21)), ModelContent::FbxBinary);
    EXPECT_EQ(kind("v 0 0 0\nf 1 2 3\n"), ModelContent::Text);
    EXPECT_EQ(kind(std::string("\0\x01\x02", 3)), ModelContent::Unknown);
}

TEST(ModelPrecheck, AcceptsEveryFileOfTheAssimpCorpusThatHasNoNesting) {
    // A sample of real files of each checked kind passes the precheck.
    const fs::path models = "/usr/share/assimp/models";
    if (!fs::exists(models)) {
        GTEST_SKIP() << "no assimp test models";
    }
    for (const char* name : {"glTF2/BoxTextured-glTF/BoxTextured.gltf",
                             "glTF2/2CylinderEngine-glTF-Binary/"
                             "2CylinderEngine.glb",
                             "Collada/duck.dae", "FBX/box.fbx", "X/test.x", "OFF/Cube.off", "PLY/cube.ply"}) {
        const fs::path file = models / name;
        if (!fs::exists(file)) {
            continue;
        }
        const base::Status status = scene::detail::precheckModel(file);
        EXPECT_TRUE(status.ok()) << name << ": " << (status ? "" : status.error());
    }
}

} // namespace
} // namespace speculum::document
