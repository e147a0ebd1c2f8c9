// glTF accessors read with every bound checked: the accessor, its buffer view and buffer, the
// stride, the sparse indices and values. A file states its counts; none is trusted before the
// bytes behind it are known to exist, so a small file claiming 4 billion elements allocates nothing.
#include "celform/model/io/animation_io_gltf.h"

#include "celform/model/io/mesh_io_common.h"

#include <cstring>
#include <limits>

namespace celform::model::animio::gltf {

namespace {

static_assert(Q_BYTE_ORDER == Q_LITTLE_ENDIAN, "glTF buffers are little-endian; add byte swapping here");

/// An accessor without a buffer view is all zeros (then usually sparse): nothing bounds its count
/// but this, the largest mesh Celform loads times the widest element (a 4 by 4 matrix).
constexpr std::size_t kMaxElementsWithoutData = std::size_t(meshio::kMaxMeshVertices);

QString typeName(int type)
{
    switch (type) {
    case TINYGLTF_TYPE_SCALAR:
        return QStringLiteral("SCALAR");
    case TINYGLTF_TYPE_VEC2:
        return QStringLiteral("VEC2");
    case TINYGLTF_TYPE_VEC3:
        return QStringLiteral("VEC3");
    case TINYGLTF_TYPE_VEC4:
        return QStringLiteral("VEC4");
    case TINYGLTF_TYPE_MAT2:
        return QStringLiteral("MAT2");
    case TINYGLTF_TYPE_MAT3:
        return QStringLiteral("MAT3");
    case TINYGLTF_TYPE_MAT4:
        return QStringLiteral("MAT4");
    default:
        return QString::number(type);
    }
}

/// One component as a double: integers as they are, or normalised.
double component(const unsigned char* p, int componentType, bool normalized)
{
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: {
        float f;
        std::memcpy(&f, p, 4);
        return f;
    }
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
        const auto v = static_cast<std::int8_t>(*p);
        return normalized ? std::max(v / 127.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return normalized ? *p / 255.0 : *p;
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
        std::int16_t v;
        std::memcpy(&v, p, 2);
        return normalized ? std::max(v / 32767.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        std::uint16_t v;
        std::memcpy(&v, p, 2);
        return normalized ? v / 65535.0 : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
        std::uint32_t v;
        std::memcpy(&v, p, 4);
        return normalized ? v / 4294967295.0 : v;
    }
    default: {
        std::int32_t v;
        std::memcpy(&v, p, 4);
        return v;
    }
    }
}

/// A run of `count` elements of `elementSize` bytes, `stride` apart, inside a buffer view.
struct Span {
    const unsigned char* data = nullptr;
    std::size_t stride = 0;
};

[[noreturn]] void fail(const Source& src, int index, const QString& what, const QString& problem)
{
    throw IoError(src.path, AnimationIo::tr("accessor %1 (%2): %3").arg(index).arg(what, problem));
}

/// The bytes of `count` elements at byteOffset in view `viewIndex`, checked against the view and
/// the view against its buffer. stride 0 takes the view's byteStride, or packs the elements.
Span spanOf(const Source& src, int index, const QString& what, int viewIndex, std::size_t byteOffset, std::size_t count,
    std::size_t elementSize, bool allowStride)
{
    const auto& views = src.model.bufferViews;
    if (viewIndex < 0 || std::size_t(viewIndex) >= views.size())
        fail(src, index, what, AnimationIo::tr("buffer view %1 does not exist").arg(viewIndex));
    const tinygltf::BufferView& view = views[std::size_t(viewIndex)];
    if (view.buffer < 0 || std::size_t(view.buffer) >= src.model.buffers.size())
        fail(src, index, what,
            AnimationIo::tr("buffer view %1 names buffer %2, which does not exist").arg(viewIndex).arg(view.buffer));
    const std::size_t bufferSize = src.model.buffers[std::size_t(view.buffer)].data.size();
    if (view.byteOffset > bufferSize || view.byteLength > bufferSize - view.byteOffset)
        fail(src, index, what,
            AnimationIo::tr("buffer view %1 covers bytes %2 to %3, but buffer %4 holds %5 bytes")
                .arg(viewIndex)
                .arg(view.byteOffset)
                .arg(view.byteOffset + view.byteLength)
                .arg(view.buffer)
                .arg(bufferSize));
    std::size_t stride = elementSize;
    if (view.byteStride != 0) {
        if (!allowStride)
            fail(src, index, what,
                AnimationIo::tr("buffer view %1 has a byteStride where none is allowed").arg(viewIndex));
        if (view.byteStride < elementSize || view.byteStride > 252)
            fail(src, index, what,
                AnimationIo::tr("buffer view %1 has a byteStride of %2 for elements of %3 bytes")
                    .arg(viewIndex)
                    .arg(view.byteStride)
                    .arg(elementSize));
        stride = view.byteStride;
    }
    // Every element takes at least one byte: a larger count cannot fit, whatever the stride.
    const std::size_t length = view.byteLength;
    if (byteOffset > length || count > length
        || (count > 0 && (count - 1) * stride + elementSize > length - byteOffset))
        fail(src, index, what,
            AnimationIo::tr("%1 elements of %2 bytes from byte %3 do not fit in buffer view %4 (%5 bytes)")
                .arg(count)
                .arg(elementSize)
                .arg(byteOffset)
                .arg(viewIndex)
                .arg(length));
    return {src.model.buffers[std::size_t(view.buffer)].data.data() + view.byteOffset + byteOffset, stride};
}

const tinygltf::Accessor& accessorAt(const Source& src, int index, const QString& what)
{
    if (index < 0 || std::size_t(index) >= src.model.accessors.size())
        throw IoError(src.path, AnimationIo::tr("%1 names accessor %2, which does not exist").arg(what).arg(index));
    return src.model.accessors[std::size_t(index)];
}

/// Reads the accessor as doubles passed to store(element, component, value).
template <typename Store> void readAccessor(const Source& src, int index, int type, const QString& what, Store store)
{
    const tinygltf::Accessor& a = accessorAt(src, index, what);
    if (a.type != type)
        fail(src, index, what, AnimationIo::tr("type %1, expected %2").arg(typeName(a.type), typeName(type)));
    const int componentSize = tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(a.componentType));
    if (componentSize <= 0 || a.componentType == TINYGLTF_COMPONENT_TYPE_DOUBLE)
        fail(src, index, what, AnimationIo::tr("unknown component type %1").arg(a.componentType));
    const int components = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(type));
    // MAT2 and MAT3 of bytes and shorts pad their columns; none of the uses here reads them.
    const std::size_t elementSize = std::size_t(componentSize) * std::size_t(components);
    if (a.bufferView >= 0) {
        const Span span = spanOf(src, index, what, a.bufferView, a.byteOffset, a.count, elementSize, true);
        for (std::size_t e = 0; e < a.count; ++e) {
            const unsigned char* p = span.data + e * span.stride;
            for (int c = 0; c < components; ++c)
                store(e, c, component(p + c * componentSize, a.componentType, a.normalized));
        }
    } else {
        if (a.count > kMaxElementsWithoutData)
            fail(src, index, what, AnimationIo::tr("%1 elements without a buffer view").arg(a.count));
        for (std::size_t e = 0; e < a.count; ++e)
            for (int c = 0; c < components; ++c)
                store(e, c, 0.0);
    }
    if (!a.sparse.isSparse)
        return;
    // Sparse substitution: `count` element indices, then as many replacement elements.
    if (a.sparse.count < 0 || std::size_t(a.sparse.count) > a.count)
        fail(src, index, what, AnimationIo::tr("%1 sparse elements of %2").arg(a.sparse.count).arg(a.count));
    const auto sparseCount = std::size_t(a.sparse.count);
    const int indexType = a.sparse.indices.componentType;
    if (indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT
        && indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        fail(src, index, what, AnimationIo::tr("sparse indices of component type %1").arg(indexType));
    if (a.sparse.indices.byteOffset < 0 || a.sparse.values.byteOffset < 0)
        fail(src, index, what, AnimationIo::tr("a negative sparse byteOffset"));
    const int indexSize = tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(indexType));
    const Span indices = spanOf(src, index, what, a.sparse.indices.bufferView, std::size_t(a.sparse.indices.byteOffset),
        sparseCount, std::size_t(indexSize), false);
    const Span values = spanOf(src, index, what, a.sparse.values.bufferView, std::size_t(a.sparse.values.byteOffset),
        sparseCount, elementSize, false);
    for (std::size_t k = 0; k < sparseCount; ++k) {
        const auto target
            = static_cast<std::size_t>(component(indices.data + k * std::size_t(indexSize), indexType, false));
        if (target >= a.count)
            fail(src, index, what,
                AnimationIo::tr("sparse element %1 replaces element %2 of %3").arg(k).arg(target).arg(a.count));
        const unsigned char* p = values.data + k * elementSize;
        for (int c = 0; c < components; ++c)
            store(target, c, component(p + c * componentSize, a.componentType, a.normalized));
    }
}

/// The output array is sized before readAccessor() checks the elements' bytes: refuse a count the
/// buffer view cannot hold first, so that what is allocated is bounded by the file's own size.
void checkCountBeforeAllocating(
    const Source& src, int index, const QString& what, const tinygltf::Accessor& a, int components)
{
    const int componentSize = tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(a.componentType));
    if (componentSize <= 0)
        fail(src, index, what, AnimationIo::tr("unknown component type %1").arg(a.componentType));
    const std::size_t elementSize = std::size_t(componentSize) * std::size_t(components);
    if (a.bufferView < 0) {
        if (a.count > kMaxElementsWithoutData)
            fail(src, index, what, AnimationIo::tr("%1 elements without a buffer view").arg(a.count));
        return;
    }
    if (std::size_t(a.bufferView) < src.model.bufferViews.size()
        && a.count > src.model.bufferViews[std::size_t(a.bufferView)].byteLength / elementSize)
        fail(src, index, what,
            AnimationIo::tr("%1 elements of %2 bytes cannot fit in buffer view %3 (%4 bytes)")
                .arg(a.count)
                .arg(elementSize)
                .arg(a.bufferView)
                .arg(src.model.bufferViews[std::size_t(a.bufferView)].byteLength));
}

} // namespace

std::vector<float> readFloats(const Source& src, int index, int type, const QString& what)
{
    const std::size_t components = std::size_t(tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(type)));
    const tinygltf::Accessor& a = accessorAt(src, index, what);
    checkCountBeforeAllocating(src, index, what, a, int(components));
    std::vector<float> out(a.count * components);
    readAccessor(src, index, type, what,
        [&](std::size_t e, int c, double v) { out[e * components + std::size_t(c)] = static_cast<float>(v); });
    return out;
}

std::vector<std::uint32_t> readIntegers(const Source& src, int index, int type, const QString& what)
{
    const std::size_t components = std::size_t(tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(type)));
    const tinygltf::Accessor& a = accessorAt(src, index, what);
    if (a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE
        && a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT
        && a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        fail(src, index, what, AnimationIo::tr("component type %1, expected unsigned integers").arg(a.componentType));
    checkCountBeforeAllocating(src, index, what, a, int(components));
    std::vector<std::uint32_t> out(a.count * components);
    readAccessor(src, index, type, what,
        [&](std::size_t e, int c, double v) { out[e * components + std::size_t(c)] = static_cast<std::uint32_t>(v); });
    return out;
}

} // namespace celform::model::animio::gltf
