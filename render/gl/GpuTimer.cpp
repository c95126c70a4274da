#include "render/gl/GpuTimer.hpp"

namespace speculum::render::gl {

void GpuTimer::begin(std::size_t index) {
    while (m_pairs.size() <= index)
        m_pairs.push_back({makeQuery(), makeQuery(), false});
    m_current = index;
    glQueryCounter(m_pairs[index].start.id(), GL_TIMESTAMP);
}

void GpuTimer::end() {
    glQueryCounter(m_pairs[m_current].stop.id(), GL_TIMESTAMP);
    m_pairs[m_current].used = true;
}

std::vector<double> GpuTimer::collect(std::size_t passCount) {
    std::vector<double> ms(passCount, -1.0);
    for (std::size_t i = 0; i < passCount && i < m_pairs.size(); ++i) {
        if (!m_pairs[i].used)
            continue;
        GLuint64 start = 0, stop = 0;
        glGetQueryObjectui64v(m_pairs[i].start.id(), GL_QUERY_RESULT, &start);
        glGetQueryObjectui64v(m_pairs[i].stop.id(), GL_QUERY_RESULT, &stop);
        ms[i] = stop >= start ? static_cast<double>(stop - start) * 1e-6 : 0.0;
        m_pairs[i].used = false;
    }
    return ms;
}

} // namespace speculum::render::gl
