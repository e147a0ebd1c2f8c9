// The reference drawings' edits (doc.drawings()): adding, importing, naming and aligning them.
#pragma once

#include "celform/model/data/camera.h"
#include "celform/model/data/project_data.h"
#include "celform/model/document/document_facade.h"
#include "celform/model/document/gesture.h"

#include <QString>

namespace celform::model {

class DrawingEdits : public DocumentFacade {
public:
    ObjectId addDrawing(Drawing drawing);
    /// Imports an image file as a drawing; returns its id. Throws IoError.
    ObjectId importDrawing(const QString& path);
    void removeDrawing(ObjectId id);
    void renameDrawing(ObjectId id, const QString& name);
    void setDrawingOpacity(ObjectId id, double opacity, GestureId gesture = {});
    /// Stores the camera aligned to a drawing (and marks it aligned).
    void setDrawingCamera(ObjectId id, const Camera& camera, GestureId gesture = {});
    /// The drawing's outline settings for Fit to Drawing. Throws EditRefused for invalid values
    /// (DrawingOutline::problem).
    void setDrawingOutline(ObjectId id, const DrawingOutline& outline, GestureId gesture = {});
    /// Makes a name unique among drawings by appending " 2", " 3", ...
    [[nodiscard]] QString uniqueDrawingName(const QString& wanted) const;

private:
    friend class Document;
    using DocumentFacade::DocumentFacade;
};

} // namespace celform::model
