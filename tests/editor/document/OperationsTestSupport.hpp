#pragma once

#include "ThreeNodeScene.hpp"
#include "editor/document/Commands.hpp"
#include "scene/model/Scene.hpp"

#include <QUndoStack>
#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace speculum::document::test {

// Scene: A, B (with children B1, B2), C; a clean undo stack.
class OperationsTest : public ::testing::Test {
protected:
    void SetUp() override {
        scene.reset(test::threeNodeScene());
        original = scene.toData();
        QObject::connect(&scene, &scene::Scene::changed, [this] { ++changes; });
    }

    scene::NodeId idOf(const std::string& name) const { return test::nodeIdByName(scene, name); }

    std::vector<std::string> namesUnder(scene::NodeId parent) const {
        std::vector<std::string> names;
        if (parent == scene::kNoNode) {
            for (const auto& node : scene.topLevelNodes()) {
                names.push_back(node->name());
            }
        } else {
            for (const auto& node : scene.findNode(parent)->children()) {
                names.push_back(node->name());
            }
        }
        return names;
    }
    std::vector<std::string> topLevelNames() const { return namesUnder(scene::kNoNode); }

    // One undo step labelled `label`; undoing it gives back the scene as it was before.
    void expectOneStepThatUndoesExactly(const std::string& label, const scene::SceneData& before) {
        EXPECT_EQ(undo.count(), 1);
        EXPECT_EQ(undo.undoText().toStdString(), label);
        const scene::SceneData after = scene.toData();
        undo.undo();
        EXPECT_EQ(scene.toData(), before) << "undo restores exactly";
        undo.redo();
        EXPECT_EQ(scene.toData(), after) << "redo does it again";
    }

    scene::Scene scene;
    QUndoStack undo;
    scene::SceneData original;
    int changes = 0;
};

} // namespace speculum::document::test
