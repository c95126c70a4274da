#include "editor/view/AdaptiveResolution.hpp"

#include <algorithm>
#include <cmath>

namespace speculum::view {

namespace {

constexpr double kStep = 1.0 / 16.0;
constexpr double kComfortable = 0.7; // well under the budget: room to raise the quality

double sixteenths(double scale) {
    return std::clamp(std::floor(scale / kStep + 1e-9) * kStep, AdaptiveResolution::kMinScale, 1.0);
}

} // namespace

void AdaptiveResolution::setBudget(double milliseconds) {
    if (std::isfinite(milliseconds) && milliseconds > 0.0) {
        m_budgetMs = milliseconds;
        m_learnt = false;
    }
}

void AdaptiveResolution::begin(double fullFrameMs) {
    if (m_learnt) {
        return;
    }
    // A full frame's cost is mostly pixels on a software rasterizer: the scale whose pixels fit.
    m_level = PreviewLevel{};
    if (fullFrameMs > m_budgetMs && std::isfinite(fullFrameMs)) {
        m_level.scale = sixteenths(std::sqrt(m_budgetMs / fullFrameMs));
    }
    m_tooSlowFrames = 0;
    m_learnt = true;
}

void AdaptiveResolution::learn(double drawMs, double totalMs, int maxDepthCut) {
    if (!std::isfinite(drawMs) || !std::isfinite(totalMs)) {
        return;
    }
    const double draw = std::max(drawMs, 0.1);
    const double total = std::max(totalMs, draw);
    maxDepthCut = std::clamp(maxDepthCut, 0, kMaxDepthCut);
    m_level.mirrorDepthCut = std::min(m_level.mirrorDepthCut, maxDepthCut);
    if (m_tooSlowFrames > 0) {
        --m_tooSlowFrames;
    }
    // What the window system adds does not shrink with the scale: the drawing gets the rest.
    const double overhead = total - draw;
    const double drawBudget = std::max(m_budgetMs - overhead, 0.25 * m_budgetMs);
    const double fitting = sixteenths(m_level.scale * std::sqrt(drawBudget / draw));

    if (total > m_budgetMs) {
        m_tooSlow = m_level;
        m_tooSlowFrames = kHoldFrames;
        if (m_level.scale > kMinScale) {
            // At least one step down: the frame's fixed costs make the square law optimistic.
            m_level.scale = std::min(fitting, sixteenths(m_level.scale - kStep));
        } else if (m_level.mirrorDepthCut < maxDepthCut) {
            ++m_level.mirrorDepthCut; // pixels are no longer what it costs: the mirror views are
        }
        return;
    }
    if (total >= kComfortable * m_budgetMs) {
        return; // within the budget: stay
    }
    // Well under it: one step back up, the mirror depth first, never onto the level found too slow.
    PreviewLevel up = m_level;
    if (up.mirrorDepthCut > 0) {
        --up.mirrorDepthCut;
    } else if (fitting > up.scale) {
        up.scale = std::min(fitting, up.scale + 0.25);
    } else {
        return;
    }
    // A level as good as one found over the budget lately is likely over it again.
    const bool asGoodAsTooSlow =
        m_tooSlowFrames > 0 &&
        (up.mirrorDepthCut < m_tooSlow.mirrorDepthCut ||
         (up.mirrorDepthCut == m_tooSlow.mirrorDepthCut && up.scale >= m_tooSlow.scale));
    if (asGoodAsTooSlow) {
        if (up.mirrorDepthCut != m_tooSlow.mirrorDepthCut || up.mirrorDepthCut != m_level.mirrorDepthCut) {
            return;
        }
        up.scale = m_tooSlow.scale - kStep; // the best scale short of it
        if (up.scale <= m_level.scale) {
            return;
        }
    }
    m_level = up;
}

} // namespace speculum::view
