// Object ids of the document: drawings, key viewpoints and highlight layers are referred to by id,
// never by address or position, so undo commands still find them after other edits.
#pragma once

#include <cstdint>

namespace celform::model {

using ObjectId = std::uint64_t; ///< stable id of a drawing, key or highlight layer, never reused in a project

} // namespace celform::model
