#include "render/passes/MirrorOcclusion.hpp"

#include "render/plan/Hasher.hpp"

namespace speculum::render::passes {

namespace {

// More distinct views than any scene shows: past it the memory is dropped (and the tests waited for).
constexpr std::size_t kMaxRemembered = 4096;

} // namespace

void MirrorOcclusion::beginFrame(const FramePlan& plan) {
    for (const auto& [key, query] : m_pending) {
        GLuint available = GL_FALSE;
        glGetQueryObjectuiv(query, GL_QUERY_RESULT_AVAILABLE, &available);
        if (available) {
            GLuint anyPassed = 0;
            glGetQueryObjectuiv(query, GL_QUERY_RESULT, &anyPassed);
            m_passedBefore[key] = anyPassed != 0;
        } else {
            m_passedBefore.erase(key); // not waiting for it now either: the next test is waited for
        }
    }
    m_pending.clear();
    if (m_passedBefore.size() > kMaxRemembered)
        m_passedBefore.clear();

    while (m_queries.size() < plan.views.size())
        m_queries.push_back(gl::makeQuery());
    m_keys.assign(plan.views.size(), 0);
    m_atSurface.assign(plan.views.size(), false);
    for (std::size_t v = 0; v < plan.views.size(); ++v) {
        const MirrorView& view = plan.views[v];
        Hasher h; // parents come before their children in the plan
        h.add(view.parent >= 0 ? m_keys[static_cast<std::size_t>(view.parent)] : std::uint64_t{0});
        h.add(view.mirror);
        m_keys[v] = h.value;
    }
    m_waits = 0;
}

bool MirrorOcclusion::mustWait(int view) const {
    const auto known = m_passedBefore.find(m_keys[static_cast<std::size_t>(view)]);
    return known == m_passedBefore.end() || !known->second;
}

GLuint MirrorOcclusion::query(int view) const {
    return m_queries[static_cast<std::size_t>(view)].id();
}

void MirrorOcclusion::waited(int view, bool anyPassed) {
    m_passedBefore[m_keys[static_cast<std::size_t>(view)]] = anyPassed;
    ++m_waits;
}

void MirrorOcclusion::countAtSurface(int view) {
    m_atSurface[static_cast<std::size_t>(view)] = true;
}

bool MirrorOcclusion::countsAtSurface(int view) const {
    return m_atSurface[static_cast<std::size_t>(view)];
}

void MirrorOcclusion::leftForLater(int view) {
    m_pending.emplace_back(m_keys[static_cast<std::size_t>(view)], query(view));
}

} // namespace speculum::render::passes
