// Importing a model in the editor as a user does it: the file is read on a worker while the window keeps
// painting, with progress and Cancel; the model comes in as its own node tree (the file's node names, one
// child per part with its material) in one undo step, at its real size (or fitted, when asked), standing on
// the ground where the view looks and beside what is already there; a broken or missing file, or a
// cancelled import, leaves the document as it was. The pick hierarchy of a big model is built on the
// worker, so the first click does not build it and the first frame does not read the file again. While
// the viewport reads a project's model file, and after the read failed, its warnings say so.
#include "base/Printable.hpp"
#include "editor/document/NodeFactory.hpp"
#include "editor/ui/ViewportModels.hpp"
#include "editor/view/AnimationClock.hpp"
#include "editor/view/Selection.hpp"
#include "scene/evaluate/PickScene.hpp"
#include "scene/evaluate/Picking.hpp"
#include "scene/evaluate/Snapshot.hpp"
#include "scene/import/MeshLibrary.hpp"
#include "scene/import/ModelImport.hpp"
#include "scene/model/Scene.hpp"
#include "support/GuiTestSupport.hpp"
#include "support/TestPaths.hpp"

#include <QAbstractButton>
#include <QFile>
#include <QMessageBox>
#include <QProgressBar>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QToolButton>
#include <QUndoStack>
#include <QWindow>
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <atomic>
#include <cstring>
#include <gtest/gtest.h>
#include <set>
#include <string>
#include <sys/stat.h>
#include <thread>

namespace {

using namespace speculum;
using namespace speculum::ui::test;
using ui::MainWindow;

const QString kEngine =
    QStringLiteral("/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb");
const QString kDuck = QStringLiteral("/usr/share/assimp/models/Collada/duck.dae");

class ModelImportGui : public ::testing::Test {
protected:
    void SetUp() override {
        m_window = std::make_unique<MainWindow>();
        m_window->resize(1280, 800);
        m_window->show();
        ASSERT_TRUE(
            waitFor([&] { return m_window->windowHandle() && m_window->windowHandle()->isExposed(); }));
        m_window->clock().setPlaying(false);
        m_window->setFitImportsToUnitBox(false);
        // A new document already holds its floor and sun; imports come after them.
        m_startNodes = m_window->scene().topLevelNodes().size();
    }

    // How many top-level nodes the imports added, and the i-th of them.
    std::size_t importedCount() const { return m_window->scene().topLevelNodes().size() - m_startNodes; }
    const speculum::scene::Node& imported(std::size_t i) const {
        return *m_window->scene().topLevelNodes().at(m_startNodes + i);
    }

    void TearDown() override {
        if (m_window) {
            m_window->setImportWorkerHook({});
            m_window->cancelImports();
            waitFor([&] { return !m_window->isImporting(); });
            m_window->undoStack().setClean();
            m_window->newProject();
            m_window.reset();
        }
    }

    // The world box of every vertex the scene draws under `root` (the whole scene when kNoNode).
    render::math::Box worldBox(speculum::scene::NodeId root = speculum::scene::kNoNode) {
        render::math::Box box;
        const auto worlds = speculum::scene::worldMatrices(m_window->scene(), 0.0);
        std::vector<speculum::scene::Warning> ignored;
        m_window->scene().forEachNode([&](const speculum::scene::Node& n) {
            if (!n.data().mesh ||
                (root != speculum::scene::kNoNode && !m_window->scene().isAncestor(root, n.id()))) {
                return;
            }
            auto mesh = m_window->viewport().meshes().get(*n.data().mesh, ignored);
            if (mesh) {
                const glm::dmat4& world = worlds.at(n.id());
                for (const glm::vec3& p : (*mesh)->positions) {
                    box.add(glm::dvec3(world * glm::dvec4(glm::dvec3(p), 1.0)));
                }
            }
        });
        return box;
    }

    std::unique_ptr<MainWindow> m_window;
    std::size_t m_startNodes = 0;
};

// The names of the file's nodes that draw meshes, and how many mesh references they hold, by Assimp itself.
struct FileFacts {
    std::set<std::string> meshNodeNames;
    int partReferences = 0;
};

void collect(const aiNode* node, FileFacts& facts) {
    if (node->mNumMeshes > 0) {
        facts.meshNodeNames.insert(node->mName.C_Str());
        facts.partReferences += int(node->mNumMeshes);
    }
    for (unsigned i = 0; i < node->mNumChildren; ++i) {
        collect(node->mChildren[i], facts);
    }
}

TEST_F(ModelImportGui, ModelComesInAsItsNodeTreeInOneUndoStepAtItsRealSizeOnTheGround) {
    if (!QFile::exists(kEngine)) {
        GTEST_SKIP() << "assimp-testmodels not installed";
    }
    Assimp::Importer importer;
    const aiScene* file = importer.ReadFile(kEngine.toStdString(), aiProcess_Triangulate);
    ASSERT_NE(file, nullptr);
    FileFacts facts;
    collect(file->mRootNode, facts);
    ASSERT_GT(facts.partReferences, 10) << "a model of many parts";

    QUndoStack& undo = m_window->undoStack();
    const int steps = undo.count();
    const glm::dvec3 focus = m_window->viewport().lookAtPoint(); // where the view looks before the import
    auto status = m_window->importModelFile(kEngine);
    ASSERT_TRUE(status.ok()) << status.error();
    EXPECT_EQ(undo.count(), steps + 1) << "the whole model is one undo step";
    ASSERT_EQ(importedCount(), 1u);
    const speculum::scene::Node& root = imported(0);
    EXPECT_EQ(root.data().name, "2CylinderEngine");
    EXPECT_EQ(m_window->selection().node(), root.id()) << "the import is selected";

    // Every node of the file that draws something is there by name; one part node per mesh reference,
    // each drawing its part of this file with the file's material.
    std::set<std::string> names;
    int parts = 0;
    std::set<std::tuple<float, float, float>> colours;
    m_window->scene().forEachNode([&](const speculum::scene::Node& n) {
        if (!m_window->scene().isAncestor(root.id(), n.id())) {
            return; // the new scene's floor and sun
        }
        names.insert(n.data().name);
        if (const auto& mesh = n.data().mesh) {
            ++parts;
            EXPECT_EQ(mesh->file, kEngine.toStdString());
            EXPECT_TRUE(mesh->part.has_value()) << n.data().name;
            ASSERT_TRUE(n.data().material) << n.data().name << " has its material";
            const auto& c = n.data().material->color;
            colours.insert({float(c.r), float(c.g), float(c.b)});
        }
    });
    for (const std::string& name : facts.meshNodeNames) {
        if (name != file->mRootNode->mName.C_Str()) { // the root takes the file's name
            EXPECT_TRUE(names.count(name)) << "the file's node " << name;
        }
    }
    EXPECT_EQ(parts, facts.partReferences);
    EXPECT_GE(colours.size(), 3u) << "the engine's parts keep their different colours";

    // Real size (the file's metres, not a unit box), standing on the ground where the view looks.
    std::vector<std::string> warnings;
    auto model = speculum::scene::importModelFile(kEngine.toStdString(), warnings);
    ASSERT_TRUE(model) << model.error();
    const glm::dvec3 fileSize = glm::dvec3(model->bounds.max) - glm::dvec3(model->bounds.min);
    const render::math::Box placed = worldBox(root.id());
    ASSERT_FALSE(placed.empty());
    const glm::dvec3 size = placed.max - placed.min;
    EXPECT_NEAR(size.x, fileSize.x, 1e-3 * fileSize.x);
    EXPECT_NEAR(size.y, fileSize.y, 1e-3 * fileSize.y);
    EXPECT_GT(std::max({size.x, size.y, size.z}), 10.0) << "the engine is hundreds of units long";
    EXPECT_NEAR(placed.min.y, 0.0, 1e-3 * size.y) << "on the ground";
    EXPECT_NEAR(placed.center().x, focus.x, 1e-3 * size.x);
    EXPECT_NEAR(placed.center().z, focus.z, 1e-3 * size.z);

    // Undo takes all of it away in one step; redo brings back the same nodes.
    const speculum::scene::SceneData imported = m_window->scene().toData();
    undo.undo();
    EXPECT_EQ(importedCount(), 0u);
    undo.redo();
    EXPECT_TRUE(m_window->scene().toData() == imported);
    ASSERT_TRUE(waitForFrames(*m_window));
    EXPECT_TRUE(m_window->viewport().rendererError().isEmpty());
}

TEST_F(ModelImportGui, SecondImportLandsBesideTheFirstAndFittingIsAnOption) {
    if (!QFile::exists(kDuck)) {
        GTEST_SKIP() << "assimp-testmodels not installed";
    }
    ASSERT_TRUE(m_window->importModelFile(kDuck).ok());
    ASSERT_TRUE(m_window->importModelFile(kDuck).ok());
    ASSERT_EQ(importedCount(), 2u);
    const auto first = worldBox(imported(0).id());
    const auto second = worldBox(imported(1).id());
    EXPECT_EQ(imported(1).data().name, "duck 2");
    EXPECT_GT(second.min.x, first.max.x) << "moved along +X past the first duck";
    EXPECT_NEAR(second.min.y, 0.0, 1e-6 * (second.max.y - second.min.y + 1.0));
    EXPECT_NEAR(second.center().z, first.center().z, 1e-6 * (first.max.z - first.min.z + 1.0));
    const glm::dvec3 realSize = first.max - first.min;
    std::vector<std::string> warnings;
    auto model = speculum::scene::importModelFile(kDuck.toStdString(), warnings);
    ASSERT_TRUE(model) << model.error();
    const glm::dvec3 fileSize = glm::dvec3(model->bounds.max) - glm::dvec3(model->bounds.min);
    EXPECT_NEAR(realSize.x, fileSize.x, 1e-4 * fileSize.x)
        << "the file's own size (with its unit), not fitted";
    EXPECT_NEAR(realSize.y, fileSize.y, 1e-4 * fileSize.y);

    // Fit Imports to a Unit Box: the largest side becomes 1, and the setting is remembered.
    QAction* fit = m_window->action(QStringLiteral("actionFitImports"));
    ASSERT_NE(fit, nullptr);
    fit->setChecked(true);
    EXPECT_TRUE(m_window->fitImportsToUnitBox()) << "kept in the settings";
    ASSERT_TRUE(m_window->importModelFile(kDuck).ok());
    const auto fitted = worldBox(imported(2).id());
    const glm::dvec3 s = fitted.max - fitted.min;
    EXPECT_NEAR(std::max({s.x, s.y, s.z}), 1.0, 1e-4);
    EXPECT_NEAR(s.x / s.y, realSize.x / realSize.y, 1e-4) << "scaled uniformly";
    EXPECT_NEAR(fitted.min.y, 0.0, 1e-4);
    EXPECT_GT(fitted.min.x, second.max.x) << "still beside the others";
    fit->setChecked(false);
    EXPECT_FALSE(m_window->fitImportsToUnitBox());
}

// A model thousands of times the scene's size: the user is asked whether to fit it to the scene (and it
// then stands about as large as the scene); a scripted import keeps its real size, says so, and the view
// frames what landed outside it.
TEST_F(ModelImportGui, AModelFarLargerThanTheSceneIsOfferedAFitAndFramed) {
    QTemporaryDir dir;
    const QString obj = dir.filePath(QStringLiteral("tower.obj"));
    {
        QFile file(obj);
        ASSERT_TRUE(file.open(QIODevice::WriteOnly));
        // A cube 20 000 units a side: centimetres read as metres, say.
        file.write("v -10000 0 -10000\nv 10000 0 -10000\nv 10000 0 10000\nv -10000 0 10000\n"
                   "v -10000 20000 -10000\nv 10000 20000 -10000\nv 10000 20000 10000\nv -10000 20000 10000\n"
                   "f 1 2 3 4\nf 5 8 7 6\nf 1 5 6 2\nf 2 6 7 3\nf 3 7 8 4\nf 4 8 5 1\n");
    }
    const double sceneSide = [&] {
        const render::math::Box b = worldBox();
        const glm::dvec3 e = b.max - b.min;
        return std::max({e.x, e.y, e.z});
    }();
    ASSERT_GT(sceneSide, 0.0);

    // As File ▸ Import Model does it: asked, and fitted.
    bool asked = false;
    QTimer answer;
    QObject::connect(&answer, &QTimer::timeout, m_window.get(), [&] {
        if (auto* box = m_window->findChild<QMessageBox*>(QStringLiteral("fitToSceneQuestion"))) {
            asked = true;
            for (QAbstractButton* b : box->buttons()) {
                if (b->text() == QStringLiteral("Fit to the Scene")) {
                    b->click();
                }
            }
        }
    });
    answer.start(50);
    bool finished = false;
    QObject::connect(m_window.get(), &MainWindow::importFinished, m_window.get(),
                     [&](const QString&, bool ok, const QString&) { finished = ok; });
    ASSERT_TRUE(m_window->startModelImport(obj, false, true).ok());
    ASSERT_TRUE(waitFor([&] { return finished; }, 60000));
    answer.stop();
    EXPECT_TRUE(asked);
    ASSERT_EQ(importedCount(), 1u);
    const render::math::Box fitted = worldBox(imported(0).id());
    const glm::dvec3 e = fitted.max - fitted.min;
    EXPECT_NEAR(std::max({e.x, e.y, e.z}), sceneSide, sceneSide * 1e-6) << "as large as the scene was";
    const auto& said = m_window->logLines();
    EXPECT_TRUE(std::any_of(said.begin(), said.end(), [](const QString& l) {
        return l.contains(QStringLiteral("Scaled to the scene's size"));
    }));
    m_window->undoStack().undo();

    // Scripted (no one to ask): its real size, said in the log, and the view frames it.
    const glm::dvec3 eyeBefore = m_window->viewport().viewCamera().position;
    ASSERT_TRUE(m_window->importModelFile(obj).ok());
    const render::math::Box real = worldBox(imported(0).id());
    EXPECT_NEAR(real.max.y - real.min.y, 20000.0, 1e-6);
    const auto& log = m_window->logLines();
    EXPECT_TRUE(std::any_of(log.begin(), log.end(), [](const QString& l) {
        return l.contains(QStringLiteral("times as large as the scene")) &&
               l.contains(QStringLiteral("real size"));
    }));
    EXPECT_TRUE(std::any_of(log.begin(), log.end(), [](const QString& l) {
        return l.contains(QStringLiteral("landed outside the view"));
    }));
    EXPECT_GT(glm::length(m_window->viewport().viewCamera().position - eyeBefore), 1000.0)
        << "the view moved out to frame it";
}

TEST_F(ModelImportGui, ReflectorSurfaceIsTheWholeFileOnTheGround) {
    if (!QFile::exists(kDuck)) {
        GTEST_SKIP() << "assimp-testmodels not installed";
    }
    ASSERT_TRUE(m_window->importModelFile(kDuck, true).ok());
    ASSERT_EQ(importedCount(), 1u);
    const speculum::scene::Node& node = imported(0);
    EXPECT_TRUE(node.data().reflector);
    ASSERT_TRUE(node.data().mesh);
    EXPECT_EQ(node.data().mesh->file, kDuck.toStdString());
    EXPECT_FALSE(node.data().mesh->part) << "the whole file is the surface";
    const auto box = worldBox(node.id());
    EXPECT_NEAR(box.min.y, 0.0, 1e-4);
    // A second one is a reflector of its own beside the first.
    ASSERT_TRUE(m_window->importModelFile(kDuck, true).ok());
    ASSERT_EQ(importedCount(), 2u);
    EXPECT_TRUE(imported(1).data().reflector);
    EXPECT_TRUE(imported(0).data().reflector);
}

TEST_F(ModelImportGui, MissingOrBrokenFilesLeaveTheDocumentUnmodified) {
    m_window->addNode(document::NewNodeKind::Teapot);
    m_window->undoStack().setClean();
    const speculum::scene::SceneData before = m_window->scene().toData();
    const int steps = m_window->undoStack().count();
    QTemporaryDir dir;
    const QString garbage = dir.filePath(QStringLiteral("garbage.obj"));
    {
        QFile f(garbage);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly));
        f.write("this is not\x01\x02 a model\n");
    }
    const QString empty = QStringLiteral("/usr/share/assimp/models/invalid/empty.obj");
    for (const QString& path : {dir.filePath(QStringLiteral("missing.glb")), garbage, empty}) {
        if (!QFile::exists(path) && path == empty) {
            continue;
        }
        auto status = m_window->importModelFile(path);
        EXPECT_FALSE(status.ok()) << path.toStdString();
        if (!status.ok()) {
            EXPECT_NE(status.error().find(QFileInfo(path).fileName().toStdString()), std::string::npos)
                << "the message names the file: " << status.error();
        }
        EXPECT_TRUE(m_window->scene().toData() == before) << path.toStdString();
        EXPECT_EQ(m_window->undoStack().count(), steps);
        EXPECT_FALSE(m_window->isModified());
    }
    EXPECT_TRUE(m_window->logLines().filter(QStringLiteral("Could not import")).size() >= 2);
}

// A binary PLY height field of cells² quads: a "big scan" of 2·cells² triangles.
QString writeBigPly(const QTemporaryDir& dir, int cells) {
    const QString path = dir.filePath(QStringLiteral("scan.ply"));
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly)) {
        return {};
    }
    const int n = cells + 1;
    const QByteArray header = QStringLiteral("ply\nformat binary_little_endian 1.0\nelement vertex %1\n"
                                             "property float x\nproperty float y\nproperty float z\n"
                                             "element face %2\nproperty list uchar int vertex_indices\n"
                                             "end_header\n")
                                  .arg(n * n)
                                  .arg(2 * cells * cells)
                                  .toLatin1();
    f.write(header);
    QByteArray vertices(n * n * 12, Qt::Uninitialized);
    float* v = reinterpret_cast<float*>(vertices.data());
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            const float x = float(i) / float(cells), z = float(j) / float(cells);
            *v++ = x;
            *v++ = 0.05f * std::sin(20.0f * x) * std::cos(17.0f * z);
            *v++ = z;
        }
    }
    f.write(vertices);
    QByteArray faces(2 * cells * cells * 13, Qt::Uninitialized);
    char* p = faces.data();
    auto face = [&](int a, int b, int c) {
        *p++ = 3;
        const int idx[3] = {a, b, c};
        std::memcpy(p, idx, 12);
        p += 12;
    };
    for (int j = 0; j < cells; ++j) {
        for (int i = 0; i < cells; ++i) {
            const int a = j * n + i, b = a + 1, c = a + n, d = c + 1;
            face(a, c, b);
            face(b, c, d);
        }
    }
    f.write(faces);
    return path;
}

TEST_F(ModelImportGui, WindowRepaintsDuringABigImportAndCancelLeavesTheDocument) {
    QTemporaryDir dir;
    const QString ply = writeBigPly(dir, 700); // 980 000 triangles
    ASSERT_FALSE(ply.isEmpty());
    ASSERT_TRUE(m_window
                    ->openProjectFile(QString::fromStdString(
                        speculum::testSourcePath("resources/scenes/teapot.speculum.json")))
                    .ok());
    ASSERT_TRUE(waitForFrames(*m_window));
    const speculum::scene::SceneData before = m_window->scene().toData();

    // Hold the worker inside the import until the window has painted a few frames: the import is
    // certainly in flight while the GUI thread draws.
    std::atomic<bool> reached{false}, hold{true};
    m_window->setImportWorkerHook([&](double) {
        reached = true;
        while (hold) {
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
    });
    ASSERT_TRUE(m_window->startModelImport(ply).ok());
    ASSERT_TRUE(waitFor([&] { return reached.load(); }));
    auto* progress = m_window->findChild<QProgressBar*>(QStringLiteral("importProgress"));
    ASSERT_NE(progress, nullptr);
    EXPECT_TRUE(progress->isVisible()) << "progress shows while importing";
    const int frames = m_window->viewport().framesRendered();
    ASSERT_TRUE(waitForFrames(*m_window, 3)) << "the viewport paints during the import";
    EXPECT_GE(m_window->viewport().framesRendered(), frames + 3);
    EXPECT_TRUE(m_window->isImporting());

    // Cancel: the status bar's button; the document stays as it was.
    auto* cancel = m_window->findChild<QToolButton*>(QStringLiteral("importCancel"));
    ASSERT_NE(cancel, nullptr);
    bool finished = false, finishedOk = true;
    QString message;
    QObject::connect(m_window.get(), &MainWindow::importFinished, m_window.get(),
                     [&](const QString&, bool ok, const QString& text) {
                         finished = true;
                         finishedOk = ok;
                         message = text;
                     });
    QTest::mouseClick(cancel, Qt::LeftButton);
    hold = false;
    ASSERT_TRUE(waitFor([&] { return finished; }));
    EXPECT_FALSE(finishedOk);
    EXPECT_EQ(message, QStringLiteral("cancelled"));
    EXPECT_FALSE(m_window->isImporting());
    EXPECT_FALSE(progress->isVisible());
    EXPECT_TRUE(m_window->scene().toData() == before);
    EXPECT_FALSE(m_window->isModified());

    // Every mesh already there has its pick hierarchy after one click.
    speculum::scene::pick(
        speculum::scene::buildPickScene(m_window->scene(), 0.0, m_window->viewport().meshes()),
        speculum::scene::Ray{{0.0, 10.0, 0.0}, {0.0, -1.0, 0.0}});

    // The same file, not cancelled: in it comes, with its pick hierarchy built on the worker, so neither
    // the next frames nor a click on it builds one (nor reads the file again: that would make new meshes).
    int progressReports = 0;
    m_window->setImportWorkerHook([&](double) { ++progressReports; });
    auto status = m_window->importModelFile(ply);
    ASSERT_TRUE(status.ok()) << status.error();
    EXPECT_GT(progressReports, 2);
    const speculum::scene::NodeId scan = m_window->scene().topLevelNodes().back()->id();
    EXPECT_EQ(m_window->scene().findNode(scan)->data().name, "scan");
    const auto builds = speculum::scene::pickCacheStats().accelBuilds;
    ASSERT_TRUE(waitForFrames(*m_window, 2));
    const render::math::Box box = worldBox(scan);
    ASSERT_FALSE(box.empty());
    const speculum::scene::PickScene picks =
        speculum::scene::buildPickScene(m_window->scene(), 0.0, m_window->viewport().meshes());
    const glm::dvec3 above(box.center().x, box.max.y + 1.0, box.center().z);
    const auto hit = speculum::scene::pick(picks, speculum::scene::Ray{above, {0.0, -1.0, 0.0}});
    ASSERT_TRUE(hit);
    EXPECT_TRUE(m_window->scene().isAncestor(scan, hit->id));
    EXPECT_EQ(speculum::scene::pickCacheStats().accelBuilds, builds) << "built on the worker, once";
}

// ---- The viewport's warnings about the model files it reads on workers ----

// The warnings of a node, in order.
std::vector<speculum::scene::Warning> about(const std::vector<speculum::scene::Warning>& warnings,
                                            const std::string& node) {
    std::vector<speculum::scene::Warning> out;
    std::copy_if(warnings.begin(), warnings.end(), std::back_inserter(out),
                 [&](const speculum::scene::Warning& w) { return w.node == node; });
    return out;
}

// While a file is read, and after its read failed, the library holds an empty stand-in for it: what the
// snapshot then says of the node (no triangles, a reflector without a mesh) gives way to one warning that
// says what is true. Warnings about other nodes and files are left as they are.
TEST(ViewportModelsGui, WarningsAboutAFileBeingReadOrFailedSayWhatIsTrue) {
    using namespace speculum::scene;
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const std::string broken = dir.filePath(QStringLiteral("broken.gltf")).toStdString();
    const std::string pipe = dir.filePath(QStringLiteral("pipe.glb")).toStdString();
    const std::string ghost = dir.filePath(QStringLiteral("ghost.obj")).toStdString();
    {
        QFile file(QString::fromStdString(broken));
        ASSERT_TRUE(file.open(QIODevice::WriteOnly));
        file.write("this is not a model\n");
    }
    ASSERT_EQ(::mkfifo(pipe.c_str(), 0600), 0);
    SceneData data;
    const auto node = [&](const std::string& name, const std::string& path) {
        NodeTree tree;
        tree.data.name = name;
        tree.data.mesh = MeshComponent::fromFile(path);
        return tree;
    };
    data.nodes = {node("Broken", broken), node("Pipe", pipe), node("Ghost", ghost)};
    data.nodes[0].data.reflector = ReflectorComponent{};
    Scene scene;
    scene.reset(data);
    MeshLibrary meshes;
    ui::ViewportModels models(meshes);
    const auto frameWarnings = [&] {
        models.prepare(scene);
        std::vector<Warning> warnings;
        snapshot(scene, 0.0, meshes, warnings);
        const std::vector<Warning> ghostWarnings = about(warnings, "Ghost");
        std::vector<Warning> corrected = models.correct(std::move(warnings));
        EXPECT_EQ(about(corrected, "Ghost"), ghostWarnings)
            << "a file nobody reads is the library's to report";
        return corrected;
    };

    // Before the worker's answer is delivered, the file is being read; the FIFO is refused at once.
    std::vector<Warning> warnings = frameWarnings();
    const std::vector<Warning> loading = about(warnings, "Broken");
    ASSERT_EQ(loading.size(), 1u) << ::testing::PrintToString(messages(warnings));
    EXPECT_EQ(loading[0], meshLoading("Broken", broken));
    EXPECT_EQ(loading[0].message, "node 'Broken': mesh loading: 'broken.gltf'...");
    const std::vector<Warning> pipeWarnings = about(warnings, "Pipe");
    ASSERT_EQ(pipeWarnings.size(), 1u) << ::testing::PrintToString(messages(warnings));
    EXPECT_EQ(pipeWarnings[0].code, WarningCode::MeshSkipped);
    EXPECT_EQ(pipeWarnings[0].file, pipe);
    EXPECT_EQ(pipeWarnings[0].message.rfind("node 'Pipe': mesh skipped: 'pipe.glb': ", 0), 0u)
        << pipeWarnings[0].message;

    // The read failed: its own error, which names the file, replaces the stand-in's "no triangles".
    ASSERT_TRUE(waitFor([&] { return !models.isLoading(); }));
    warnings = frameWarnings();
    std::vector<std::string> notes;
    const auto read = importModelFile(broken, notes);
    ASSERT_FALSE(read.ok());
    EXPECT_EQ(about(warnings, "Broken"),
              std::vector<Warning>{meshSkipped("Broken", broken, base::printable(read.error(), 200))})
        << ::testing::PrintToString(messages(warnings));
    EXPECT_EQ(about(warnings, "Pipe"), pipeWarnings);
}

} // namespace
