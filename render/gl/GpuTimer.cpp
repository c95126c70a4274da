#include "render/gl/GpuTimer.hpp"

namespace speculum::render::gl {

std::size_t GpuTimer::stamp() {
    if (m_used == m_stamps.size())
        m_stamps.push_back(makeQuery());
    glQueryCounter(m_stamps[m_used].id(), GL_TIMESTAMP);
    return m_used++;
}

void GpuTimer::begin(std::size_t index) {
    if (m_spans.size() <= index)
        m_spans.resize(index + 1);
    m_current = index;
    m_spans[index].start = m_atBoundary ? m_used - 1 : stamp();
    m_atBoundary = false;
}

void GpuTimer::end() {
    m_spans[m_current].stop = stamp();
    m_spans[m_current].timed = true;
    m_atBoundary = true;
}

std::vector<double> GpuTimer::collect(std::size_t passCount) {
    std::vector<GLuint64> times(m_used, 0);
    for (std::size_t i = 0; i < m_used; ++i)
        glGetQueryObjectui64v(m_stamps[i].id(), GL_QUERY_RESULT, &times[i]);
    std::vector<double> ms(passCount, -1.0);
    for (std::size_t i = 0; i < passCount && i < m_spans.size(); ++i) {
        Span& span = m_spans[i];
        if (!span.timed)
            continue;
        const GLuint64 start = times[span.start], stop = times[span.stop];
        ms[i] = stop >= start ? static_cast<double>(stop - start) * 1e-6 : 0.0;
        span.timed = false;
    }
    m_used = 0;
    m_atBoundary = false;
    return ms;
}

} // namespace speculum::render::gl
