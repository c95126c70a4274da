#include "render/math/Projection.hpp"
#include "render/plan/Planner.hpp"

#include <algorithm>

namespace speculum::render {

namespace {

// Image pixels → the tile's own pixels: clipped to the tile and counted from its corner (empty: none).
math::PixelRect toTile(const math::PixelRect& rect, const math::PixelRect& tile) {
    const math::PixelRect clipped{std::max(rect.x0, tile.x0), std::max(rect.y0, tile.y0),
                                  std::min(rect.x1, tile.x1), std::min(rect.y1, tile.y1)};
    if (clipped.empty())
        return {};
    return {clipped.x0 - tile.x0, clipped.y0 - tile.y0, clipped.x1 - tile.x0, clipped.y1 - tile.y0};
}

} // namespace

void restrictToTile(FramePlan& plan, const math::PixelRect& tile, const PlanViewport& image) {
    std::vector<bool> outside(plan.views.size(), false);
    for (std::size_t i = 0; i < plan.views.size(); ++i) {
        MirrorView& view = plan.views[i];
        view.projection = math::tileProjection(view.projection, tile.x0, tile.y0, tile.width(), tile.height(),
                                               image.width, image.height);
        // pixelArea stays the whole image's: it is what the plan was decided on and what reports show.
        view.rect = toTile(view.rect, tile);
        outside[i] = view.rect.empty();
    }
    // A view's rectangle lies within its parent's, so a view outside the tile has every descendant outside
    // it too: dropping each such view's own passes drops whole subtrees.
    std::erase_if(plan.passes, [&](const PlannedPass& pass) {
        return pass.view >= 0 && outside[static_cast<std::size_t>(pass.view)];
    });
    // The passes draw the tile's pixels of what they would have drawn in the image.
    for (PlannedPass& pass : plan.passes)
        if (pass.writes.scissor)
            pass.writes.scissor = toTile(*pass.writes.scissor, tile);
}

} // namespace speculum::render
