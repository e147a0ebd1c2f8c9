// The sRGB encoding of the overlays (srgb_bytes.h): the offline renderer's exact quantiser, so a
// line over the model has the bytes `celform render` writes.
#include "celform/views/overlays/srgb_bytes.h"

#include "celform/algorithms/srgb_encode.h"

namespace celform::views {

std::uint8_t srgbByte(float linear)
{
    return algo::srgbEncode8(linear);
}

} // namespace celform::views
