// The render options dialog (render_dialog.h).
#include "editor/dialogs/render_dialog.h"

#include "celform/model/document/document.h"
#include "celform/model/render/render_output.h"
#include "celform/views/viewport/viewport.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QStandardItemModel>
#include <QStandardPaths>
#include <QToolButton>
#include <QVBoxLayout>

namespace celform::app {
namespace {

// QSettings keys: the folder and format are shared; the frames are per kind.
const char* const kFolderKey = "render/folder";
const char* const kFormatKey = "render/format";
const char* const kCameraKey = "render/camera";
const char* const kWidthKey = "render/width";
const char* const kHeightKey = "render/height";
const char* const kPassKey = "render/pass";
const char* const kStereoKey = "render/stereo";
const char* const kStyleKey = "render/style";
const char* const kLinesKey = "render/lines";
const char* const kOpenKey = "render/openWhenDone";
const char* const kFirstFrameKey = "render/sequence/first";
const char* const kLastFrameKey = "render/sequence/last";

/// Camera choices are stored by kind and name, so they survive reopening the project.
const char* const kCameraShot = "shot";
const char* const kCameraRender = "render";
const char* const kCameraView = "view";
const char* const kCameraDefault = "default";
const QString kCameraKeyPrefix = QStringLiteral("key:");
const QString kCameraDrawingPrefix = QStringLiteral("drawing:");

/// Selects the item whose data is value, if there is one.
/// The outputs `celform render` writes: the raster formats, and .svg (the lines pass as strokes).
bool isOutputSuffix(const QString& suffix)
{
    return model::renderSuffixes().contains(suffix) || suffix == QLatin1String("svg");
}

void selectData(QComboBox* combo, const QVariant& value)
{
    const int index = combo->findData(value);
    if (index >= 0)
        combo->setCurrentIndex(index);
}

/// "1,048,576" with the locale's grouping; GB with one decimal.
QString gigabytes(qint64 bytes)
{
    return QLocale().toString(double(std::max<qint64>(bytes, 0)) / 1e9, 'f', 1);
}

} // namespace

RenderDialog::RenderDialog(Kind kind, model::Document* document, views::Viewport* viewport, QWidget* parent)
    : QDialog(parent)
    , m_kind(kind)
    , m_document(document)
    , m_viewport(viewport)
{
    setObjectName(kind == Kind::Image ? QStringLiteral("renderImageDialog") : QStringLiteral("renderSequenceDialog"));
    setWindowTitle(kind == Kind::Image ? tr("Render Image") : tr("Render Sequence"));
    buildForm();
    fillCameras();
    restoreOptions();
    updateState();
}

void RenderDialog::buildForm()
{
    auto* form = new QFormLayout;
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);

    // Output file (a pattern for sequences) with a Browse button.
    m_output = new QLineEdit(this);
    m_output->setObjectName(QStringLiteral("renderOutput"));
    m_output->setMinimumWidth(360);
    m_output->setToolTip(m_kind == Kind::Image
            ? tr("The image to write: .png, .tif or .jpg (8-bit sRGB) or .exr (linear float; every pass as channels "
                 "unless a pass is chosen)")
            : tr("The frames to write: a run of # becomes the zero-padded frame number (shot_####.png); without one, "
                 "_0001 and so on go before the suffix"));
    auto* browse = new QToolButton(this);
    browse->setText(tr("Browse…"));
    browse->setToolTip(tr("Choose the output file and its format"));
    connect(browse, &QToolButton::clicked, this, &RenderDialog::browse);
    auto* outputRow = new QHBoxLayout;
    outputRow->addWidget(m_output, 1);
    outputRow->addWidget(browse);
    // A row of a layout gets no buddy from QFormLayout: label the line edit itself.
    auto* outputLabel = new QLabel(m_kind == Kind::Image ? tr("&Output file:") : tr("&Output files:"), this);
    outputLabel->setBuddy(m_output);
    form->addRow(outputLabel, outputRow);
    m_files = new QLabel(this);
    m_files->setObjectName(QStringLiteral("renderFiles"));
    m_files->setTextInteractionFlags(Qt::TextSelectableByMouse);
    form->addRow(QString(), m_files);

    // The camera: as `celform render` without camera options (the render camera or a framed
    // default view), the editor's current view, or a key's or an aligned drawing's camera.
    m_camera = new QComboBox(this);
    m_camera->setObjectName(QStringLiteral("renderCamera"));
    m_camera->setToolTip(tr("The camera the render looks through; the shape is the view-dependent blend for it"));
    form->addRow(tr("&Camera:"), m_camera);

    const auto spinFrame = [this](const QString& name, const QString& tip) {
        auto* spin = new QSpinBox(this);
        spin->setObjectName(name);
        spin->setRange(-model::kMaxFrame, model::kMaxFrame);
        spin->setToolTip(tip);
        spin->setAccelerated(true);
        return spin;
    };
    if (m_kind == Kind::Image) {
        m_frame = spinFrame(QStringLiteral("renderFrame"),
            tr("The frame to render: the animated base model, the keys' deformations and the highlights at it"));
        form->addRow(tr("&Frame:"), m_frame);
    } else {
        m_firstFrame = spinFrame(QStringLiteral("renderFirstFrame"), tr("The first frame of the sequence"));
        m_lastFrame = spinFrame(QStringLiteral("renderLastFrame"), tr("The last frame of the sequence (included)"));
        auto* frames = new QHBoxLayout;
        frames->addWidget(m_firstFrame, 1);
        auto* to = new QLabel(tr("to"), this);
        to->setBuddy(m_lastFrame);
        frames->addWidget(to);
        frames->addWidget(m_lastFrame, 1);
        auto* framesLabel = new QLabel(tr("&Frames:"), this);
        framesLabel->setBuddy(m_firstFrame);
        form->addRow(framesLabel, frames);
    }

    // Size: presets and width × height.
    m_sizePreset = new QComboBox(this);
    m_sizePreset->setObjectName(QStringLiteral("renderSizePreset"));
    m_sizePreset->setToolTip(tr("Common image sizes; editing the width or height makes it a custom size"));
    const QSize presets[] = {{1280, 720}, {1920, 1080}, {3840, 2160}, {2048, 858}, {1024, 1024}};
    const QString presetNames[]
        = {tr("HD 720p"), tr("Full HD 1080p"), tr("UHD 4K"), tr("2K scope (2.39:1)"), tr("Square 1024")};
    for (std::size_t i = 0; i < std::size(presets); ++i)
        m_sizePreset->addItem(
            tr("%1 (%2 × %3)").arg(presetNames[i]).arg(presets[i].width()).arg(presets[i].height()), presets[i]);
    if (m_viewport && m_viewport->width() > 0)
        m_sizePreset->addItem(
            tr("Viewport (%1 × %2)").arg(m_viewport->width()).arg(m_viewport->height()), m_viewport->size());
    m_sizePreset->addItem(tr("Custom"), QSize());
    form->addRow(tr("Si&ze:"), m_sizePreset);
    const auto spinSide = [this](const QString& name, const QString& tip) {
        auto* spin = new QSpinBox(this);
        spin->setObjectName(name);
        spin->setRange(1, model::kMaxRenderSide);
        spin->setSuffix(tr(" px"));
        spin->setToolTip(tip);
        spin->setAccelerated(true);
        return spin;
    };
    m_width = spinSide(QStringLiteral("renderWidth"), tr("Image width in pixels (at most 16384)"));
    m_height = spinSide(QStringLiteral("renderHeight"), tr("Image height in pixels (at most 16384)"));
    auto* sizeRow = new QHBoxLayout;
    sizeRow->addWidget(m_width, 1);
    auto* times = new QLabel(QStringLiteral("×"), this);
    times->setBuddy(m_height);
    sizeRow->addWidget(times);
    sizeRow->addWidget(m_height, 1);
    auto* sizeLabel = new QLabel(tr("&Width × height:"), this);
    sizeLabel->setBuddy(m_width);
    form->addRow(sizeLabel, sizeRow);
    connect(m_sizePreset, qOverload<int>(&QComboBox::activated), this, [this](int index) {
        const QSize size = m_sizePreset->itemData(index).toSize();
        if (!size.isValid())
            return;
        const QSignalBlocker blockWidth(m_width), blockHeight(m_height);
        m_width->setValue(size.width());
        m_height->setValue(size.height());
        updateState();
    });
    const auto sizeEdited = [this] {
        selectData(m_sizePreset, QSize(m_width->value(), m_height->value()));
        if (m_sizePreset->currentData().toSize() != QSize(m_width->value(), m_height->value()))
            selectData(m_sizePreset, QSize());
        updateState();
    };
    connect(m_width, qOverload<int>(&QSpinBox::valueChanged), this, sizeEdited);
    connect(m_height, qOverload<int>(&QSpinBox::valueChanged), this, sizeEdited);

    // Passes, stereo and the look overrides of `celform render`.
    m_pass = new QComboBox(this);
    m_pass->setObjectName(QStringLiteral("renderPass"));
    m_pass->setToolTip(tr("What to write: the finished picture (beauty) or one of the renderer's passes; an .exr "
                          "can hold every pass as named channels"));
    const std::pair<QString, QString> passes[]
        = {{QStringLiteral("beauty"), tr("Beauty (the finished picture)")}, {QStringLiteral("lines"), tr("Lines")},
            {QStringLiteral("tone"), tr("Tone")}, {QStringLiteral("highlights"), tr("Highlights")},
            {QStringLiteral("depth"), tr("Depth")}, {QStringLiteral("normal"), tr("Normals")},
            {QStringLiteral("id"), tr("Object ids")}, {QString(), tr("All passes (EXR channels)")}};
    for (const auto& [name, label] : passes)
        m_pass->addItem(label, name);
    form->addRow(tr("&Pass:"), m_pass);

    m_stereo = new QComboBox(this);
    m_stereo->setObjectName(QStringLiteral("renderStereo"));
    m_stereo->setToolTip(tr("Render both eyes and compose them (the look's stereo settings); a stereo render "
                            "writes the beauty pass"));
    const std::pair<algo::StereoOutput, QString> stereoModes[] = {{algo::StereoOutput::Off, tr("Off (mono)")},
        {algo::StereoOutput::Anaglyph, tr("Anaglyph")}, {algo::StereoOutput::Dubois, tr("Dubois anaglyph")},
        {algo::StereoOutput::HalfColor, tr("Half-colour anaglyph")},
        {algo::StereoOutput::SideBySide, tr("Side by side")}, {algo::StereoOutput::TopBottom, tr("Top-bottom")}};
    for (const auto& [mode, label] : stereoModes)
        m_stereo->addItem(label, int(mode));
    form->addRow(tr("&Stereo:"), m_stereo);

    m_style = new QComboBox(this);
    m_style->setObjectName(QStringLiteral("renderStyle"));
    m_style->setToolTip(tr("Shade this render in another style; the project's look is not changed"));
    m_style->addItem(tr("As in the project"), -1);
    const std::pair<model::ShadingStyle, QString> styles[]
        = {{model::ShadingStyle::Toon, tr("Toon")}, {model::ShadingStyle::Gooch, tr("Gooch")},
            {model::ShadingStyle::Comic, tr("Comic")}, {model::ShadingStyle::Lambert, tr("Lambert")}};
    for (const auto& [style, label] : styles)
        m_style->addItem(label, int(style));
    form->addRow(tr("St&yle:"), m_style);

    m_lines = new QComboBox(this);
    m_lines->setObjectName(QStringLiteral("renderLines"));
    m_lines->setToolTip(tr("Draw the lines or not in this render; the project's look is not changed"));
    m_lines->addItem(tr("As in the project"), -1);
    m_lines->addItem(tr("On"), 1);
    m_lines->addItem(tr("Off"), 0);
    form->addRow(tr("&Lines:"), m_lines);

    // An .svg output holds the lines pass as vector strokes (docs/lines.md, "Vector lines").
    m_svgTones = new QCheckBox(tr("Tone regions in the SVG"), this);
    m_svgTones->setObjectName(QStringLiteral("renderSvgTones"));
    m_svgTones->setToolTip(tr("With an .svg output: the tone regions as filled layers under the strokes, for "
                              "editing in Inkscape or Illustrator"));
    form->addRow(QString(), m_svgTones);
    connect(m_svgTones, &QCheckBox::toggled, this, &RenderDialog::updateState);

    m_open
        = new QCheckBox(m_kind == Kind::Image ? tr("Open the image when done") : tr("Open the folder when done"), this);
    m_open->setObjectName(QStringLiteral("renderOpenWhenDone"));
    m_open->setToolTip(tr("Show the result in the desktop's image viewer or file manager"));
    form->addRow(QString(), m_open);

    m_problem = new QLabel(this);
    m_problem->setObjectName(QStringLiteral("renderProblem"));
    m_problem->setWordWrap(true);
    m_problem->setStyleSheet(QStringLiteral("color: #c0392b;"));

    m_buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    m_buttons->button(QDialogButtonBox::Ok)->setText(tr("&Render"));
    m_buttons->button(QDialogButtonBox::Ok)
        ->setToolTip(tr("Render with these options; Cancel in the progress "
                        "window stops between frames"));
    connect(m_buttons, &QDialogButtonBox::accepted, this, &RenderDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &RenderDialog::reject);

    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_problem);
    layout->addStretch(1);
    layout->addWidget(m_buttons);

    for (QComboBox* combo : {m_camera, m_pass, m_stereo, m_style, m_lines})
        connect(combo, qOverload<int>(&QComboBox::currentIndexChanged), this, &RenderDialog::updateState);
    for (QSpinBox* spin : {m_frame, m_firstFrame, m_lastFrame})
        if (spin)
            connect(spin, qOverload<int>(&QSpinBox::valueChanged), this, &RenderDialog::updateState);
    connect(m_output, &QLineEdit::textChanged, this, &RenderDialog::updateState);
}

void RenderDialog::fillCameras()
{
    const model::ProjectData* data = m_document ? &m_document->data() : nullptr;
    // The camera path at each frame, as `celform render` without camera options.
    if (data && !data->look.cameraPath.empty())
        m_camera->addItem(tr("Shot camera (the camera path)"), QString::fromLatin1(kCameraShot));
    if (data && data->look.renderCamera)
        m_camera->addItem(tr("Render camera (the project's)"), QString::fromLatin1(kCameraRender));
    if (m_viewport)
        m_camera->addItem(tr("Current view"), QString::fromLatin1(kCameraView));
    m_camera->addItem(tr("Framed default view"), QString::fromLatin1(kCameraDefault));
    if (!data)
        return;
    for (const model::KeyViewpoint& key : data->keys)
        m_camera->addItem(tr("Key: %1").arg(key.name), kCameraKeyPrefix + key.name);
    for (const model::Drawing& drawing : data->drawings)
        if (drawing.aligned)
            m_camera->addItem(tr("Drawing: %1").arg(drawing.name), kCameraDrawingPrefix + drawing.name);
}

void RenderDialog::restoreOptions()
{
    QSettings settings;
    const QString projectPath = m_document ? m_document->filePath() : QString();
    QString folder = settings.value(kFolderKey).toString();
    if (folder.isEmpty() || !QFileInfo(folder).isDir())
        folder = !projectPath.isEmpty() ? QFileInfo(projectPath).absolutePath()
                                        : QStandardPaths::writableLocation(QStandardPaths::PicturesLocation);
    if (folder.isEmpty())
        folder = QDir::homePath();
    m_output->setText(defaultOutput(folder, settings.value(kFormatKey, QStringLiteral("png")).toString()));

    // The shot camera when there is a camera path (what the shot is seen through); else the
    // remembered choice, at first the render camera when there is one, as `celform render`.
    if (m_camera->findData(QString::fromLatin1(kCameraShot)) >= 0)
        selectData(m_camera, QString::fromLatin1(kCameraShot));
    else
        selectData(m_camera, settings.value(kCameraKey, QString::fromLatin1(kCameraRender)));
    const int current = m_document ? m_document->data().currentFrame : 0;
    if (m_frame)
        m_frame->setValue(current);
    if (m_firstFrame) {
        m_firstFrame->setValue(settings.value(kFirstFrameKey, current).toInt());
        m_lastFrame->setValue(settings.value(kLastFrameKey, current + 23).toInt());
    }
    m_width->setValue(settings.value(kWidthKey, 1280).toInt());
    m_height->setValue(settings.value(kHeightKey, 720).toInt());
    selectData(m_sizePreset, QSize(m_width->value(), m_height->value()));
    if (m_sizePreset->currentData().toSize() != QSize(m_width->value(), m_height->value()))
        selectData(m_sizePreset, QSize());
    selectData(m_pass, settings.value(kPassKey, QStringLiteral("beauty")));
    selectData(m_stereo, settings.value(kStereoKey, int(algo::StereoOutput::Off)));
    selectData(m_style, settings.value(kStyleKey, -1));
    selectData(m_lines, settings.value(kLinesKey, -1));
    m_open->setChecked(settings.value(kOpenKey, true).toBool());
}

void RenderDialog::saveOptions() const
{
    QSettings settings;
    const QFileInfo output(m_output->text());
    settings.setValue(kFolderKey, output.absolutePath());
    settings.setValue(kFormatKey, output.suffix().toLower());
    settings.setValue(kCameraKey, m_camera->currentData());
    if (m_firstFrame) {
        settings.setValue(kFirstFrameKey, m_firstFrame->value());
        settings.setValue(kLastFrameKey, m_lastFrame->value());
    }
    settings.setValue(kWidthKey, m_width->value());
    settings.setValue(kHeightKey, m_height->value());
    settings.setValue(kPassKey, m_pass->currentData());
    settings.setValue(kStereoKey, m_stereo->currentData());
    settings.setValue(kStyleKey, m_style->currentData());
    settings.setValue(kLinesKey, m_lines->currentData());
    settings.setValue(kOpenKey, m_open->isChecked());
}

QString RenderDialog::defaultOutput(const QString& folder, const QString& suffix) const
{
    const QString projectPath = m_document ? m_document->filePath() : QString();
    QString base = QFileInfo(projectPath).completeBaseName();
    if (base.isEmpty() && m_document)
        base = QFileInfo(m_document->data().baseMeshName).completeBaseName();
    if (base.isEmpty())
        base = tr("render");
    const QString ext = isOutputSuffix(suffix) ? suffix : QStringLiteral("png");
    const QString name = m_kind == Kind::Image ? base + QLatin1Char('.') + ext : base + QStringLiteral("_####.") + ext;
    return QDir(folder).filePath(name);
}

void RenderDialog::browse()
{
    const std::pair<QString, QString> formats[]
        = {{QStringLiteral("png"), tr("PNG images (*.png)")}, {QStringLiteral("exr"), tr("OpenEXR images (*.exr)")},
            {QStringLiteral("tif"), tr("TIFF images (*.tif *.tiff)")},
            {QStringLiteral("jpg"), tr("JPEG images (*.jpg *.jpeg)")},
            {QStringLiteral("svg"), tr("SVG vector lines (*.svg)")}};
    QStringList filters;
    QString selected;
    QString suffix = QFileInfo(m_output->text()).suffix().toLower();
    suffix = suffix == QLatin1String("tiff") ? QStringLiteral("tif")
        : suffix == QLatin1String("jpeg")    ? QStringLiteral("jpg")
                                             : suffix;
    for (const auto& [ext, filter] : formats) {
        filters << filter;
        if (ext == suffix)
            selected = filter;
    }
    // A pattern's # would make the file dialog ask about a file that is never written.
    QString path
        = QFileDialog::getSaveFileName(this, windowTitle(), m_output->text(), filters.join(QStringLiteral(";;")),
            &selected, m_kind == Kind::Sequence ? QFileDialog::DontConfirmOverwrite : QFileDialog::Options());
    if (path.isEmpty())
        return;
    if (!isOutputSuffix(QFileInfo(path).suffix().toLower())) {
        QString ext = QStringLiteral("png");
        for (const auto& [e, filter] : formats)
            if (filter == selected)
                ext = e;
        path += QLatin1Char('.') + ext;
    }
    m_output->setText(QDir::toNativeSeparators(path));
}

model::RenderJob RenderDialog::job() const
{
    model::RenderJob job;
    job.output = QDir::fromNativeSeparators(m_output->text().trimmed());
    if (!job.output.isEmpty())
        job.output = QFileInfo(job.output).absoluteFilePath();
    if (m_frame) {
        job.firstFrame = job.lastFrame = m_frame->value();
    } else {
        job.firstFrame = m_firstFrame->value();
        job.lastFrame = m_lastFrame->value();
    }
    job.size = QSize(m_width->value(), m_height->value());
    job.pass = m_pass->currentData().toString();
    if (job.writesVectorLines()) {
        job.pass = QStringLiteral("lines");
        job.svgTones = m_svgTones->isChecked();
    }
    job.stereo = algo::StereoOutput(m_stereo->currentData().toInt());
    if (const int style = m_style->currentData().toInt(); style >= 0)
        job.style = model::ShadingStyle(style);
    if (const int lines = m_lines->currentData().toInt(); lines >= 0)
        job.lines = lines == 1;
    // The camera: none set is the camera path at each frame, else the render camera, else a framed
    // default view (model::renderJobCamera), as `celform render` without camera options.
    const QString camera = m_camera->currentData().toString();
    const model::ProjectData* data = m_document ? &m_document->data() : nullptr;
    if (camera == QLatin1String(kCameraShot)) {
        // Left unset: each frame's camera comes from the path.
    } else if (camera == QLatin1String(kCameraRender) && data && data->look.renderCamera) {
        job.camera = *data->look.renderCamera;
    } else if (camera == QLatin1String(kCameraView) && m_viewport) {
        job.camera = m_viewport->camera();
    } else if (camera == QLatin1String(kCameraDefault)) {
        job.view = model::defaultRenderView();
    } else if (data && camera.startsWith(kCameraKeyPrefix)) {
        if (const auto* key = data->keyByName(camera.mid(kCameraKeyPrefix.size())))
            job.camera = key->camera;
    } else if (data && camera.startsWith(kCameraDrawingPrefix)) {
        if (const auto* drawing = data->drawingByName(camera.mid(kCameraDrawingPrefix.size())))
            job.camera = drawing->camera;
    }
    return job;
}

bool RenderDialog::openWhenDone() const
{
    return m_open->isChecked();
}

QString RenderDialog::problem() const
{
    if (!m_document || !m_document->hasMesh())
        return tr("The project has no base model to render.");
    const model::RenderJob j = job();
    if (j.output.isEmpty())
        return tr("Choose the output file.");
    const QFileInfo output(j.output);
    if (!isOutputSuffix(output.suffix().toLower()))
        return tr("%1: the output must end in .png, .exr, .tif, .jpg or .svg.").arg(QDir::toNativeSeparators(j.output));
    if (j.writesVectorLines() && (j.stereo == algo::StereoOutput::Dubois || j.stereo == algo::StereoOutput::HalfColor))
        return tr("An SVG holds one group of strokes per eye: choose mono, anaglyph, side by side or top-bottom.");
    if (!output.absoluteDir().exists())
        return tr("%1: the folder does not exist.").arg(QDir::toNativeSeparators(output.absolutePath()));
    if (output.isDir())
        return tr("%1 is a folder: give a file name.").arg(QDir::toNativeSeparators(j.output));
    if (j.lastFrame < j.firstFrame)
        return tr("The last frame comes before the first.");
    if (j.frameCount() > model::kMaxFramesPerRender)
        return tr("At most %L1 frames can be rendered at a time.").arg(model::kMaxFramesPerRender);
    if (qint64(j.size.width()) * j.size.height() > model::kMaxRenderPixels)
        return tr("%1 × %2 is more than 8192 × 8192 pixels, the most the renderer takes.")
            .arg(j.size.width())
            .arg(j.size.height());
    const qint64 available = model::availableRenderMemory();
    if (j.bytesNeeded() > available)
        return tr("%1 × %2 needs about %3 GB of memory to render, and %4 GB are available.")
            .arg(j.size.width())
            .arg(j.size.height())
            .arg(gigabytes(j.bytesNeeded()), gigabytes(available));
    return {};
}

void RenderDialog::updateState()
{
    const QString suffix = QFileInfo(m_output->text()).suffix().toLower();
    const bool stereo = algo::StereoOutput(m_stereo->currentData().toInt()) != algo::StereoOutput::Off;
    // A stereo render writes the composed beauty; every pass at once needs an .exr; an .svg is the
    // lines pass as strokes.
    const bool svg = suffix == QLatin1String("svg");
    m_pass->setEnabled(!stereo && !svg);
    if (svg)
        selectData(m_pass, QStringLiteral("lines"));
    else if (stereo)
        selectData(m_pass, QStringLiteral("beauty"));
    m_svgTones->setEnabled(svg);
    const int allPasses = m_pass->findData(QString());
    if (auto* model = qobject_cast<QStandardItemModel*>(m_pass->model()))
        if (QStandardItem* item = model->item(allPasses))
            item->setEnabled(suffix == QLatin1String("exr"));
    if (m_pass->currentIndex() == allPasses && suffix != QLatin1String("exr"))
        selectData(m_pass, QStringLiteral("beauty"));

    const model::RenderJob j = job();
    if (!j.output.isEmpty() && isOutputSuffix(suffix)) {
        const QString first = QDir::toNativeSeparators(j.framePath(j.firstFrame));
        m_files->setText(j.isSequence()
                ? tr("Writes %1 … %2 (%L3 frames)")
                      .arg(QFileInfo(first).fileName(), QFileInfo(j.framePath(j.lastFrame)).fileName())
                      .arg(j.frameCount())
                : tr("Writes %1").arg(QFileInfo(first).fileName()));
    } else {
        m_files->clear();
    }
    const QString why = problem();
    m_problem->setText(why);
    m_problem->setVisible(!why.isEmpty());
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(why.isEmpty());
}

void RenderDialog::accept()
{
    const QString why = problem();
    if (!why.isEmpty()) {
        updateState();
        return;
    }
    const model::RenderJob j = job();
    int existing = 0;
    for (int f = j.firstFrame; f <= j.lastFrame; ++f)
        existing += QFileInfo(j.framePath(f)).isFile() ? 1 : 0;
    if (existing > 0) {
        const QString question = j.isSequence()
            ? tr("%L1 of the %L2 files already exist. Replace them?").arg(existing).arg(j.frameCount())
            : tr("%1 already exists. Replace it?").arg(QDir::toNativeSeparators(j.output));
        if (QMessageBox::question(this, windowTitle(), question, QMessageBox::Yes | QMessageBox::No, QMessageBox::No)
            != QMessageBox::Yes)
            return;
    }
    saveOptions();
    QDialog::accept();
}

} // namespace celform::app
