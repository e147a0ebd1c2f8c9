// The drawings' extracted outlines, kept (outline_cache.h).
#include "celform/views/overlays/outline_cache.h"

#include "celform/model/analysis/drawing_fit.h"

#include <algorithm>

namespace celform::views {

std::shared_ptr<const algo::Outline> OutlineCache::outline(const model::Drawing& drawing)
{
    const qint64 image = drawing.image.cacheKey();
    for (std::size_t i = 0; i < m_entries.size(); ++i) {
        const Entry& e = m_entries[i];
        if (e.drawing == drawing.id && e.settings == drawing.outline && e.image == image) {
            std::rotate(
                m_entries.begin(), m_entries.begin() + std::ptrdiff_t(i), m_entries.begin() + std::ptrdiff_t(i) + 1);
            return m_entries.front().outline;
        }
    }
    Entry entry{
        drawing.id, drawing.outline, image, std::make_shared<const algo::Outline>(model::drawingOutline(drawing))};
    ++m_extractions;
    m_entries.insert(m_entries.begin(), std::move(entry));
    if (m_entries.size() > kEntries)
        m_entries.pop_back();
    return m_entries.front().outline;
}

} // namespace celform::views
