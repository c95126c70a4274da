#pragma once

#include "editor/document/Properties.hpp"

namespace speculum::document::groups {

// The node's component groups, one function each; nodeComponents() (Properties.cpp) builds them once, in
// the order the inspector shows them.

// NodeProperties.cpp
ComponentInfo nodeGroup();
ComponentInfo transformGroup();
ComponentInfo meshGroup();
ComponentInfo materialGroup();
ComponentInfo lightGroup();
ComponentInfo animationGroup();

// (mirror and reflector: NodeProperties.cpp too)
ComponentInfo mirrorGroup();
ComponentInfo reflectorGroup();

} // namespace speculum::document::groups
