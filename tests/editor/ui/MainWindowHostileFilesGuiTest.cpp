// Hostile files in the editor: with a document open and modified, a user drops (Import or Open)
// a file of each hostile class: a FIFO, a model whose node graph is a DAG or a chain 100 000 deep, a model
// that references a FIFO (a glTF buffer, an OBJ mtllib), a Collada file nested 100 000 deep, a project that
// is a FIFO, /dev/zero behind a symlink, a project with duplicate keys or a light of 1e39. Each time an
// error box names the file and the cause, the event loop keeps running (a timer ticks, the viewport draws)
// and the open document is exactly as it was: the same nodes, undo stack, modified flag and project path.
//
// A FIFO that the editor wrongly reads would block a reader for good, and CI with it: the test holds every
// FIFO's write end open (O_RDWR | O_NONBLOCK, so no open() blocks), and a watchdog thread closes and
// unlinks them at a deadline (a blocked read then ends with EOF and the test fails instead of hanging);
// should the process still be stuck after that, the watchdog ends it with a message.
#include "editor/document/NodeFactory.hpp"
#include "editor/ui/AccuracyPanel.hpp"
#include "editor/view/AnimationClock.hpp"
#include "scene/model/Scene.hpp"
#include "support/GuiTestSupport.hpp"
#include "support/TestPaths.hpp"

#include <QAbstractButton>
#include <QApplication>
#include <QDropEvent>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QMessageBox>
#include <QMimeData>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTimer>
#include <QUndoStack>
#include <QUrl>
#include <QWindow>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <mutex>
#include <string>
#include <sys/stat.h>
#include <thread>
#include <unistd.h>
#include <vector>

namespace {

using namespace speculum;
using namespace speculum::ui::test;
using ui::MainWindow;

const QString kTeapotProject =
    QString::fromStdString(speculum::testSourcePath("resources/scenes/teapot.speculum.json"));

// Holds the FIFOs' write ends; see the file comment.
class FifoWatchdog {
public:
    explicit FifoWatchdog(std::chrono::seconds deadline)
        : m_thread([this, deadline] { run(deadline); }) {}

    ~FifoWatchdog() {
        {
            std::lock_guard lock(m_mutex);
            m_done = true;
        }
        m_wake.notify_all();
        m_thread.join();
        releaseFifos();
    }

    // Makes a FIFO at path and opens its write end; false when that fails.
    bool makeFifo(const QString& path) {
        const std::string p = QFile::encodeName(path).toStdString();
        if (::mkfifo(p.c_str(), 0600) != 0) {
            return false;
        }
        const int fd = ::open(p.c_str(), O_RDWR | O_NONBLOCK);
        if (fd < 0) {
            return false;
        }
        std::lock_guard lock(m_mutex);
        m_fifos.push_back({p, fd});
        return true;
    }

    bool fired() const { return m_fired; }

private:
    void run(std::chrono::seconds deadline) {
        std::unique_lock lock(m_mutex);
        if (m_wake.wait_for(lock, deadline, [this] { return m_done; })) {
            return;
        }
        // A reader is stuck on a FIFO (or the GUI thread is): give every reader EOF, and no new open().
        m_fired = true;
        std::fprintf(stderr, "test_hostile_files: watchdog: still running after %lld s; closing the FIFOs\n",
                     static_cast<long long>(deadline.count()));
        for (auto& [path, fd] : m_fifos) {
            ::unlink(path.c_str());
            ::close(fd);
            fd = -1;
        }
        if (m_wake.wait_for(lock, std::chrono::seconds(20), [this] { return m_done; })) {
            return;
        }
        std::fprintf(stderr, "test_hostile_files: watchdog: the editor hangs; ending the test process\n");
        std::_Exit(3);
    }

    void releaseFifos() {
        for (auto& [path, fd] : m_fifos) {
            if (fd >= 0) {
                ::close(fd);
            }
            ::unlink(path.c_str());
        }
        m_fifos.clear();
    }

    std::mutex m_mutex;
    std::condition_variable m_wake;
    bool m_done = false;
    std::atomic<bool> m_fired{false};
    std::vector<std::pair<std::string, int>> m_fifos;
    std::thread m_thread;
};

// What the user sees of the open document.
struct DocumentState {
    QStringList nodes; // names in tree order
    int undoCount = 0;
    int undoIndex = 0;
    bool modified = false;
    QString projectPath;

    bool operator==(const DocumentState&) const = default;
};

std::ostream& operator<<(std::ostream& out, const DocumentState& s) {
    return out << s.nodes.size() << " nodes (" << s.nodes.join(QStringLiteral(", ")).toStdString()
               << "), undo " << s.undoIndex << "/" << s.undoCount << (s.modified ? ", modified" : ", clean")
               << ", project '" << s.projectPath.toStdString() << "'";
}

DocumentState stateOf(MainWindow& window) {
    DocumentState s;
    window.scene().forEachNode(
        [&](const speculum::scene::Node& node) { s.nodes << QString::fromStdString(node.name()); });
    s.undoCount = window.undoStack().count();
    s.undoIndex = window.undoStack().index();
    s.modified = window.isModified();
    s.projectPath = window.scene().projectPath();
    return s;
}

// Answers every message box while it lives: "Discard" to the unsaved-changes prompt (so a dropped project is
// opened over the modified document), OK to an error, whose text it keeps.
class BoxAnswerer : public QObject {
public:
    BoxAnswerer() {
        connect(&m_timer, &QTimer::timeout, this, [this] {
            auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
            if (!box || !box->isVisible()) {
                return;
            }
            if (QAbstractButton* discard = box->button(QMessageBox::Discard)) {
                ++prompts;
                discard->click();
                return;
            }
            errors << box->windowTitle() + QStringLiteral(": ") + box->text();
            if (QAbstractButton* ok = box->button(QMessageBox::Ok)) {
                ok->click();
            } else {
                box->reject();
            }
        });
        m_timer.start(10);
    }

    QStringList errors;
    int prompts = 0;

private:
    QTimer m_timer;
};

struct Outcome {
    QStringList errors; // the text of every error box
    int prompts = 0;    // unsaved-changes prompts answered
    int ticks = 0;      // of a 10 ms timer, while the drop and what it started ran
    qint64 ms = 0;
    bool finished = false;
};

class HostileFilesGui : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(m_dir.isValid());
        m_window = std::make_unique<MainWindow>();
        m_window->resize(900, 600);
        m_window->show();
        ASSERT_TRUE(
            waitFor([&] { return m_window->windowHandle() && m_window->windowHandle()->isExposed(); }));
        m_window->clock().setPlaying(false);
        m_window->setFitImportsToUnitBox(false);
        // A document with a file and an unsaved edit: what a failed Import or Open must not touch.
        auto opened = m_window->openProjectFile(kTeapotProject);
        ASSERT_TRUE(opened.ok()) << opened.error();
        ASSERT_TRUE(m_window->addNode(document::NewNodeKind::Mirror).ok());
        ASSERT_TRUE(waitForFrames(*m_window));
        m_before = stateOf(*m_window);
        ASSERT_TRUE(m_before.modified);
        ASSERT_EQ(m_before.undoCount, 1);
    }

    void TearDown() override {
        if (m_window) {
            m_window->cancelImports();
            waitFor([&] { return !m_window->isImporting(); }, 20000);
            m_window->undoStack().setClean();
            m_window->newProject();
            m_window.reset();
        }
    }

    QString path(const QString& name) const { return m_dir.filePath(name); }

    QString write(const QString& name, const QByteArray& bytes) const {
        QFile file(path(name));
        EXPECT_TRUE(file.open(QIODevice::WriteOnly | QIODevice::Truncate)) << name.toStdString();
        file.write(bytes);
        return path(name);
    }

    // Drops `file` on the window as a user drags it from a file manager (a project opens, a model is
    // imported) and runs the event loop until the import it started has ended and its box was answered.
    Outcome drop(const QString& file) {
        Outcome out;
        BoxAnswerer boxes;
        QTimer ticker;
        QObject::connect(&ticker, &QTimer::timeout, [&] { ++out.ticks; });
        ticker.start(10);
        QElapsedTimer clock;
        clock.start();

        QMimeData mime;
        mime.setUrls({QUrl::fromLocalFile(file)});
        QDropEvent event(QPointF(200, 200), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
        // Straight to the window's handler: QApplication only delivers a drop inside a drag it runs itself.
        static_cast<QObject*>(m_window.get())->event(&event);
        out.finished = waitFor(
            [&] {
                return !m_window->isImporting() && !boxes.errors.isEmpty() &&
                       QApplication::activeModalWidget() == nullptr;
            },
            25000);
        // Whatever the end of the import queued (a repaint, a second box) runs too.
        waitFor([] { return false; }, 100);
        out.errors = boxes.errors;
        out.prompts = boxes.prompts;
        out.ms = clock.elapsed();
        return out;
    }

    // What every case must show: one error box naming the file and the cause, a live event loop, a
    // viewport that still draws and the document as it was.
    void expectRefused(const Outcome& out, const QString& file, const QString& cause,
                       const FifoWatchdog* watchdog = nullptr) {
        const QString name = QFileInfo(file).fileName();
        EXPECT_TRUE(out.finished) << name.toStdString() << ": no error box within 25 s";
        if (watchdog) {
            EXPECT_FALSE(watchdog->fired()) << name.toStdString() << ": a read blocked on a FIFO";
        }
        ASSERT_FALSE(out.errors.isEmpty()) << name.toStdString() << ": no error was shown";
        const QString text = out.errors.join(QLatin1Char('\n'));
        EXPECT_TRUE(text.contains(name)) << "the error does not name the file: " << text.toStdString();
        EXPECT_TRUE(text.contains(QRegularExpression(cause, QRegularExpression::CaseInsensitiveOption)))
            << "the error does not name the cause (/" << cause.toStdString() << "/): " << text.toStdString();
        EXPECT_GT(out.ticks, 0) << "the event loop did not run";
        EXPECT_LT(out.ms, 20000) << name.toStdString() << " took " << out.ms << " ms";
        EXPECT_EQ(stateOf(*m_window), m_before) << "the document changed";
        EXPECT_TRUE(waitForFrames(*m_window)) << "the viewport stopped drawing";
        EXPECT_FALSE(m_window->isImporting());
    }

    QTemporaryDir m_dir;
    std::unique_ptr<MainWindow> m_window;
    DocumentState m_before;
};

// A one-triangle glTF buffer as a data URI (36 bytes of float positions).
QByteArray triangleBufferJson(const QString& uri = {}) {
    const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const QByteArray bytes(reinterpret_cast<const char*>(positions), sizeof positions);
    const QString u = uri.isEmpty() ? QStringLiteral("data:application/octet-stream;base64,") +
                                          QString::fromLatin1(bytes.toBase64())
                                    : uri;
    return QStringLiteral(R"("buffers":[{"byteLength":36,"uri":"%1"}],
"bufferViews":[{"buffer":0,"byteLength":36}],
"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],
"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}])")
        .arg(u)
        .toUtf8();
}

// A glTF whose nodes 0..levels-1 each list the next one `copies` times; the last one draws the triangle.
QByteArray gltfChain(int levels, int copies) {
    QByteArray nodes;
    nodes.reserve(levels * 24);
    for (int i = 0; i < levels; ++i) {
        nodes += i ? "," : "";
        QByteArray children;
        for (int c = 0; c < copies; ++c) {
            children += (c ? "," : "") + QByteArray::number(i + 1);
        }
        nodes += "{\"children\":[" + children + "]}";
    }
    nodes += ",{\"mesh\":0}";
    return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[)" + nodes + "]," +
           triangleBufferJson() + "}";
}

// ---- Import ----

TEST_F(HostileFilesGui, ImportOfAFifoIsRefusedAtOnce) {
    FifoWatchdog watchdog(std::chrono::seconds(15));
    const QString fifo = path(QStringLiteral("pipe.gltf"));
    ASSERT_TRUE(watchdog.makeFifo(fifo));
    const Outcome out = drop(fifo);
    expectRefused(out, fifo, QStringLiteral("FIFO|named pipe"), &watchdog);
    EXPECT_LT(out.ms, 2000) << "a FIFO is refused by a stat, not read";
}

TEST_F(HostileFilesGui, ImportOfAGltfDagIsRefusedWithoutUnfoldingIt) {
    FifoWatchdog watchdog(std::chrono::seconds(40));
    const QString file = write(QStringLiteral("dag.gltf"), gltfChain(40, 2)); // 2^40 instances
    const Outcome out = drop(file);
    expectRefused(out, file, QStringLiteral("instance"));
}

TEST_F(HostileFilesGui, ImportOfAGltfChain100000DeepIsRefused) {
    FifoWatchdog watchdog(std::chrono::seconds(40));
    const QString file = write(QStringLiteral("deep.gltf"), gltfChain(100000, 1));
    const Outcome out = drop(file);
    expectRefused(out, file, QStringLiteral("deep|depth|nest"));
}

TEST_F(HostileFilesGui, ImportOfAGltfWhoseBufferIsAFifoIsRefused) {
    FifoWatchdog watchdog(std::chrono::seconds(15));
    ASSERT_TRUE(watchdog.makeFifo(path(QStringLiteral("data.bin"))));
    const QString file = write(QStringLiteral("fifo-buffer.gltf"),
                               R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],)"
                               R"("nodes":[{"mesh":0}],)" +
                                   triangleBufferJson(QStringLiteral("data.bin")) + "}");
    const Outcome out = drop(file);
    expectRefused(out, file, QStringLiteral("data\\.bin.*(FIFO|named pipe)|(FIFO|named pipe).*data\\.bin"),
                  &watchdog);
}

TEST_F(HostileFilesGui, ImportOfAnObjWhoseMtllibIsAFifoIsRefused) {
    FifoWatchdog watchdog(std::chrono::seconds(15));
    ASSERT_TRUE(watchdog.makeFifo(path(QStringLiteral("pipe.mtl"))));
    const QString file = write(QStringLiteral("fifo-mtl.obj"), "mtllib pipe.mtl\n"
                                                               "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                                               "usemtl red\nf 1 2 3\n");
    const Outcome out = drop(file);
    expectRefused(out, file, QStringLiteral("pipe\\.mtl.*(FIFO|named pipe)|(FIFO|named pipe).*pipe\\.mtl"),
                  &watchdog);
}

TEST_F(HostileFilesGui, ImportOfACollada100000DeepIsRefused) {
    FifoWatchdog watchdog(std::chrono::seconds(40));
    QByteArray xml = R"(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
<library_visual_scenes><visual_scene id="s">)";
    constexpr int kDepth = 100000;
    xml.reserve(kDepth * 40);
    for (int i = 0; i < kDepth; ++i) {
        xml += "<node id=\"n" + QByteArray::number(i) + "\">";
    }
    for (int i = 0; i < kDepth; ++i) {
        xml += "</node>";
    }
    xml +=
        R"(</visual_scene></library_visual_scenes><scene><instance_visual_scene url="#s"/></scene></COLLADA>)";
    const QString file = write(QStringLiteral("deep.dae"), xml);
    const Outcome out = drop(file);
    expectRefused(out, file, QStringLiteral("deep|depth|nest"));
}

// ---- Open ----

QByteArray teapotProject() {
    QFile file(kTeapotProject);
    EXPECT_TRUE(file.open(QIODevice::ReadOnly));
    return file.readAll();
}

TEST_F(HostileFilesGui, OpenOfAFifoProjectIsRefusedAtOnce) {
    FifoWatchdog watchdog(std::chrono::seconds(15));
    const QString fifo = path(QStringLiteral("pipe.speculum.json"));
    ASSERT_TRUE(watchdog.makeFifo(fifo));
    const Outcome out = drop(fifo);
    expectRefused(out, fifo, QStringLiteral("FIFO|named pipe"), &watchdog);
    EXPECT_EQ(out.prompts, 1) << "the unsaved-changes prompt comes first";
    EXPECT_LT(out.ms, 5000);
}

TEST_F(HostileFilesGui, OpenOfDevZeroBehindASymlinkIsRefused) {
    FifoWatchdog watchdog(std::chrono::seconds(15));
    const QString link = path(QStringLiteral("zero.speculum.json"));
    ASSERT_TRUE(QFile::link(QStringLiteral("/dev/zero"), link));
    const Outcome out = drop(link);
    expectRefused(out, link, QStringLiteral("device"), &watchdog);
    EXPECT_LT(out.ms, 5000);
}

TEST_F(HostileFilesGui, OpenOfAProjectWithDuplicateKeysIsRefused) {
    QByteArray json = teapotProject();
    // The second "intensity" of the light would silently win.
    const int at = json.indexOf("\"intensity\": 1");
    ASSERT_GT(at, 0);
    json.insert(at, "\"intensity\": 5,\n        ");
    const QString file = write(QStringLiteral("duplicate.speculum.json"), json);
    const Outcome out = drop(file);
    expectRefused(out, file, QStringLiteral("duplicate"));
}

TEST_F(HostileFilesGui, OpenOfAProjectWithALightOf1e39IsRefused) {
    QByteArray json = teapotProject();
    const int at = json.indexOf("\"intensity\": 1");
    ASSERT_GT(at, 0);
    json.replace(at, int(sizeof("\"intensity\": 1") - 1), "\"intensity\": 1e39");
    const QString file = write(QStringLiteral("bright.speculum.json"), json);
    const Outcome out = drop(file);
    expectRefused(out, file, QStringLiteral("intensity"));
}

// ---- Models an opened project references: read on workers, never by the viewport's paintGL ----

TEST_F(HostileFilesGui, ModelsOfAnOpenedProjectThatAreHostileAreReadOffTheGuiThread) {
    FifoWatchdog watchdog(std::chrono::seconds(40));
    ASSERT_TRUE(watchdog.makeFifo(path(QStringLiteral("data.bin"))));
    ASSERT_TRUE(watchdog.makeFifo(path(QStringLiteral("pipe.glb"))));
    write(QStringLiteral("dag.gltf"), gltfChain(40, 2));
    write(QStringLiteral("fifo-buffer.gltf"),
          R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)" +
              triangleBufferJson(QStringLiteral("data.bin")) + "}");
    QByteArray json = teapotProject();
    const int at = json.indexOf("\"nodes\": [");
    ASSERT_GT(at, 0);
    json.insert(at + int(sizeof("\"nodes\": [") - 1),
                R"({"name": "Dag", "mesh": {"file": "dag.gltf"}},
                   {"name": "Buffer", "mesh": {"file": "fifo-buffer.gltf"}},
                   {"name": "Pipe", "mesh": {"file": "pipe.glb"}},)");
    const QString project = write(QStringLiteral("hostile-models.speculum.json"), json);

    int ticks = 0;
    QTimer ticker;
    QObject::connect(&ticker, &QTimer::timeout, [&] { ++ticks; });
    ticker.start(10);
    QElapsedTimer clock;
    clock.start();
    m_window->undoStack().setClean();
    auto opened = m_window->openProjectFile(project);
    ASSERT_TRUE(opened.ok()) << opened.error() << " (the project itself is fine)";
    EXPECT_LT(clock.elapsed(), 3000) << "opening does not read the models";
    // The viewport draws meanwhile; the files are refused on workers.
    const int ticksBefore = ticks;
    EXPECT_TRUE(waitForFrames(*m_window)) << "the viewport stopped drawing";
    EXPECT_GT(ticks, ticksBefore) << "the event loop did not run while the models were read";
    EXPECT_FALSE(watchdog.fired()) << "a read blocked on a FIFO";
    EXPECT_LT(clock.elapsed(), 20000);

    const QString log = m_window->logLines().join(QLatin1Char('\n'));
    auto mentions = [&](const QString& pattern) {
        return log.contains(QRegularExpression(pattern, QRegularExpression::CaseInsensitiveOption));
    };
    // The first frame after the open drew while the file was still being read: the viewport did not wait
    // on the read, it was off the GUI thread.
    EXPECT_TRUE(mentions(QStringLiteral("Dag.*mesh loading.*dag\\.gltf"))) << log.toStdString();
    EXPECT_TRUE(mentions(QStringLiteral("Dag.*dag\\.gltf.*instance"))) << log.toStdString();
    EXPECT_TRUE(mentions(QStringLiteral("Buffer.*fifo-buffer\\.gltf.*(FIFO|named pipe)")))
        << log.toStdString();
    EXPECT_TRUE(mentions(QStringLiteral("Pipe.*pipe\\.glb.*(FIFO|named pipe)"))) << log.toStdString();
    EXPECT_EQ(m_window->scene().projectPath(), QFileInfo(project).absoluteFilePath());
    EXPECT_FALSE(m_window->isModified());
}

// ---- The Accuracy panel's bench results ----

TEST_F(HostileFilesGui, LoadingBenchResultsThatAreAFifoOrADeviceIsRefusedAtOnce) {
    FifoWatchdog watchdog(std::chrono::seconds(15));
    const QString fifo = path(QStringLiteral("results.json"));
    ASSERT_TRUE(watchdog.makeFifo(fifo));
    const QString zero = path(QStringLiteral("zero-results.json"));
    ASSERT_TRUE(QFile::link(QStringLiteral("/dev/zero"), zero));
    QElapsedTimer clock;
    clock.start();
    const auto fromFifo = m_window->accuracyPanel().loadSweepFile(fifo);
    const auto fromDevice = m_window->accuracyPanel().loadSweepFile(zero);
    EXPECT_LT(clock.elapsed(), 2000);
    EXPECT_FALSE(watchdog.fired()) << "a read blocked on a FIFO";
    ASSERT_FALSE(fromFifo.ok());
    EXPECT_NE(fromFifo.error().find("results.json"), std::string::npos) << fromFifo.error();
    EXPECT_NE(fromFifo.error().find("FIFO"), std::string::npos) << fromFifo.error();
    ASSERT_FALSE(fromDevice.ok());
    EXPECT_NE(fromDevice.error().find("device"), std::string::npos) << fromDevice.error();
    EXPECT_EQ(stateOf(*m_window), m_before);
}

} // namespace
