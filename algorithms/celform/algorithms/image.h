// A float RGBA image in linear light, the currency of the offline renderer and its passes.
#pragma once

#include <Eigen/Core>

#include <vector>

namespace celform::algo {

struct ImageRGBA {
    int width = 0;
    int height = 0;
    std::vector<float> pixels; ///< width * height * 4, row 0 at the top, linear RGB + alpha

    ImageRGBA() = default;
    ImageRGBA(int w, int h, const Eigen::Vector4f& fill = Eigen::Vector4f::Zero())
        : width(w)
        , height(h)
        , pixels(std::size_t(w) * std::size_t(h) * 4)
    {
        for (std::size_t i = 0; i < pixels.size(); i += 4)
            for (int c = 0; c < 4; ++c)
                pixels[i + std::size_t(c)] = fill[c];
    }
    [[nodiscard]] float* at(int x, int y)
    {
        return pixels.data() + (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4;
    }
    [[nodiscard]] const float* at(int x, int y) const
    {
        return pixels.data() + (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4;
    }
};

/// sRGB transfer function (IEC 61966-2-1) and its inverse, per channel: the exact piecewise
/// curves (linear segment below 0.0031308 linear / 0.04045 encoded), evaluated in double. No
/// clamping: values below 0 follow the linear segment, above 1 the power curve; quantisation
/// clamps when a file is written.
float linearToSrgb(float linear);
float srgbToLinear(float encoded);

} // namespace celform::algo
