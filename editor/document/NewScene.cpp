#include "editor/document/NewScene.hpp"

#include "editor/document/NodeFactory.hpp"

namespace speculum::document {

scene::SceneData newSceneData() {
    scene::SceneData data;
    data.camera.position = {0.0, 2.5, 6.0};
    data.camera.target = {0.0, 0.5, 0.0};
    data.camera.fovY = 50.0;
    data.camera.near = 0.1;
    data.camera.far = 100.0;

    scene::NodeTree floor = makeNode(NewNodeKind::Plane);
    floor.data.name = "Floor";
    floor.data.transform.scale = {5.0, 1.0, 5.0}; // the plane spans −1..1: a 10 × 10 floor
    data.nodes.push_back(std::move(floor));

    // From above, in front and to the right, so the shading shows which way things face.
    scene::NodeTree sun = makeNode(NewNodeKind::DirectionalLight, {0.0, 3.0, 0.0});
    sun.data.name = "Sun";
    sun.data.transform.rotate = {35.0, 0.0, -25.0};
    data.nodes.push_back(std::move(sun));
    return data;
}

} // namespace speculum::document
