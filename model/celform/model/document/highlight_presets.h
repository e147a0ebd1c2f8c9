// Starting points for stylized highlights: the two worked examples of Anjyo & Hiramitsu (2003),
// the car window of Figure 5 and the crescent of Figure 6, as highlight layers.
#pragma once

#include "celform/model/data/project_data.h"

#include <vector>

namespace celform::model {

enum class HighlightPreset {
    Window, ///< rotation, directional scaling and split on a nearly flat part (Figure 5b)
    Crescent, ///< a layer minus a hidden copy of itself moved along du and dv (Figure 6)
};

/// The layers of a preset keyed at frame, on base's patch with its guide and smoothing (8 rounds
/// when base has none). Their names are the preset's and must still be made unique.
std::vector<HighlightTrack> highlightPresetLayers(HighlightPreset preset, const HighlightTrack& base, int frame);

/// The operation a layer gets when the artist adds one of this type: the identity where the type
/// has one, squareness 0.2 with n = 2 for squaring (the paper's squarest setting).
algo::HighlightOperation neutralHighlightOperation(algo::HighlightOperationType type);

} // namespace celform::model
