// The extracted outline of a drawing, the target of Fit to Drawing (model::drawingOutline with the
// settings saved with the drawing), kept per drawing, settings and image: the viewport's outline
// mode and the Properties panel's live figures read it at every paint and edit, and extracting a
// megapixel drawing again each time would cost tens of milliseconds.
#pragma once

#include "celform/algorithms/outline.h"
#include "celform/model/data/project_data.h"

#include <memory>
#include <vector>

namespace celform::views {

class OutlineCache {
public:
    /// The drawing's outline with its saved settings, extracted on first use (an outline that
    /// failed says why in its error; model::outlineProblem words it).
    std::shared_ptr<const algo::Outline> outline(const model::Drawing& drawing);
    /// Forgets every outline.
    void clear() { m_entries.clear(); }
    /// How many extractions ran (for the tests of the cache).
    [[nodiscard]] int extractions() const { return m_extractions; }

private:
    struct Entry {
        model::ObjectId drawing = 0;
        model::DrawingOutline settings;
        qint64 image = 0; ///< QImage::cacheKey of the image it was extracted from
        std::shared_ptr<const algo::Outline> outline;
    };
    static constexpr std::size_t kEntries = 4; ///< a few drawings of a model sheet
    std::vector<Entry> m_entries; ///< most recently used first
    int m_extractions = 0;
};

} // namespace celform::views
