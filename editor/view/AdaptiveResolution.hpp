#pragma once

namespace speculum::view {

// How much a preview frame gives up while the view is navigated or a handle dragged (the demos
// must stay interactive on software GL): the fraction of the width and height it is drawn at, and how
// many levels of mirror nesting it leaves out. Full quality is {1, 0}.
struct PreviewLevel {
    double scale = 1.0;
    int mirrorDepthCut = 0;
    bool reduced() const { return scale < 1.0 || mirrorDepthCut > 0; }
    bool operator==(const PreviewLevel&) const = default;
};

// Chooses the preview level from measured frame times, so a frame takes about the budget: the scale first
// (a frame's pixel work goes with its square), down to a quarter; then, when even that is too slow (the
// cost is in the number of mirror views, not in pixels), one mirror level less at a time, down to one.
// Going back up is slower than going down (only when well under the budget, one step at a time, depth
// first), and sizes come in sixteenths, so a steady cost settles on one level instead of flickering between
// two (each new size also reallocates the frame's buffers). Qt-free: the viewport feeds it.
class AdaptiveResolution {
public:
    static constexpr double kMinScale = 0.25;
    static constexpr double kDefaultBudgetMs = 40.0;
    static constexpr int kMaxDepthCut = 16;

    double budget() const { return m_budgetMs; }
    // Milliseconds a preview frame should take, drawing and getting on screen; not positive and finite:
    // ignored. Forgets what was learnt.
    void setBudget(double milliseconds);

    // A gesture starts. What the last one learnt is kept unless forget() was called since (the view's size
    // changed); otherwise it starts from the cost of a full-quality frame (fullFrameMs, 0 when unknown):
    // the scale whose pixels would fit the budget.
    void begin(double fullFrameMs);
    // Starts the next gesture from scratch.
    void forget() { m_learnt = false; }

    // The level the next preview frame is drawn at.
    const PreviewLevel& level() const { return m_level; }

    // A preview frame drawn at level() took drawMs to draw and totalMs until it was on screen (drawing,
    // and what the window system adds; totalMs ≥ drawMs, or equal to it when unknown). maxDepthCut: the
    // levels of mirror nesting the scene has beyond the first (cutting more would change nothing).
    void learn(double drawMs, double totalMs, int maxDepthCut);

    // A level found too slow is not tried again for this many frames (the view's cost changes as it
    // moves, so not for the rest of the gesture either).
    static constexpr int kHoldFrames = 20;

private:
    double m_budgetMs = kDefaultBudgetMs;
    PreviewLevel m_level;
    bool m_learnt = false;
    // The lowest level found over the budget lately, which going back up stops short of.
    PreviewLevel m_tooSlow;
    int m_tooSlowFrames = 0;
};

} // namespace speculum::view
