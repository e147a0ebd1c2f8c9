// Operation rows of the Highlights dock; every edit is a document operation on the layer's id.
#include "celform/views/panels/highlight_operations.h"

#include "celform/model/document/document.h"
#include "celform/model/data/io_error.h"
#include "celform/views/panels/gesture_tracker.h"

#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QMenu>
#include <QSignalBlocker>
#include <QToolButton>
#include <QVBoxLayout>

namespace celform::views {
namespace {

/// The strings keep the Highlights dock's translation context.
struct Text {
    Q_DECLARE_TR_FUNCTIONS(celform::views::HighlightPanel)
};

/// Range, step, decimals and the paper's names of an operation's two parameters.
struct ParameterSpec {
    double min, max, step;
    int decimals;
    const char* name;
    const char* tip;
};

std::pair<ParameterSpec, ParameterSpec> operationSpecs(algo::HighlightOperationType type)
{
    using T = algo::HighlightOperationType;
    switch (type) {
    case T::Translation:
        return {{-2, 2, 0.05, 3, QT_TRANSLATE_NOOP("celform::views::HighlightPanel", "α"),
                    QT_TRANSLATE_NOOP("celform::views::HighlightPanel", "alpha: moves the highlight along du")},
            {-2, 2, 0.05, 3, QT_TRANSLATE_NOOP("celform::views::HighlightPanel", "β"),
                QT_TRANSLATE_NOOP("celform::views::HighlightPanel", "beta: moves the highlight along dv")}};
    case T::Rotation:
        return {{-360, 360, 5, 1, QT_TRANSLATE_NOOP("celform::views::HighlightPanel", "angle"),
                    QT_TRANSLATE_NOOP("celform::views::HighlightPanel",
                        "Angle in degrees, du turning towards dv: turns the frame of later operations")},
            {0, 0, 0, 0, nullptr, nullptr}};
    case T::DirectionalScaling:
        return {
            {0, 1, 0.05, 3, QT_TRANSLATE_NOOP("celform::views::HighlightPanel", "δ"),
                QT_TRANSLATE_NOOP("celform::views::HighlightPanel", "delta in [0, 1]: stretches the area along du")},
            {0, 0, 0, 0, nullptr, nullptr}};
    case T::Split:
        return {{0, 5, 0.05, 3, QT_TRANSLATE_NOOP("celform::views::HighlightPanel", "γ1"),
                    QT_TRANSLATE_NOOP("celform::views::HighlightPanel", "gamma1 >= 0: cuts the area across du")},
            {0, 5, 0.05, 3, QT_TRANSLATE_NOOP("celform::views::HighlightPanel", "γ2"),
                QT_TRANSLATE_NOOP("celform::views::HighlightPanel", "gamma2 >= 0: cuts the area across dv")}};
    case T::Squaring:
        return {{0, 1, 0.05, 3, QT_TRANSLATE_NOOP("celform::views::HighlightPanel", "σ"),
                    QT_TRANSLATE_NOOP("celform::views::HighlightPanel",
                        "sigma in [0, 1]: squareness of the area (about 0.2 is squarest)")},
            {1, 16, 1, 0, QT_TRANSLATE_NOOP("celform::views::HighlightPanel", "n"),
                QT_TRANSLATE_NOOP("celform::views::HighlightPanel", "n >= 1: exponent of the squaring")}};
    }
    return {};
}

QString operationTitle(algo::HighlightOperationType type)
{
    using T = algo::HighlightOperationType;
    switch (type) {
    case T::Translation:
        return Text::tr("Translate");
    case T::Rotation:
        return Text::tr("Rotate");
    case T::DirectionalScaling:
        return Text::tr("Scale");
    case T::Split:
        return Text::tr("Split");
    case T::Squaring:
        return Text::tr("Square");
    }
    return {};
}

} // namespace

HighlightOperationsBox::HighlightOperationsBox(model::Document* document, QWidget* parent)
    : QGroupBox(Text::tr("Operations (in order)"), parent)
    , m_document(document)
{
    auto* layout = new QVBoxLayout(this);
    m_rows = new QVBoxLayout;
    layout->addLayout(m_rows);
    m_add = new QToolButton(this);
    m_add->setText(Text::tr("Add Operation"));
    m_add->setToolTip(Text::tr("Append an operation on the highlight's vector field to every key of the layer"));
    m_add->setPopupMode(QToolButton::InstantPopup);
    auto* menu = new QMenu(m_add);
    using T = algo::HighlightOperationType;
    for (T type : {T::Translation, T::Rotation, T::DirectionalScaling, T::Split, T::Squaring}) {
        QAction* a = menu->addAction(operationTitle(type));
        connect(a, &QAction::triggered, this,
            [this, type] { run([&] { m_document->highlights().addHighlightOperation(m_layer, type); }); });
    }
    m_add->setMenu(menu);
    layout->addWidget(m_add, 0, Qt::AlignLeft);
}

void HighlightOperationsBox::run(const std::function<void()>& operation)
{
    try {
        operation();
    } catch (const model::EditRefused&) {
        showLayer(m_layer); // never stored: the rows go back to the layer
    }
}

void HighlightOperationsBox::rebuildRows(const std::vector<algo::HighlightOperationType>& types)
{
    while (QLayoutItem* item = m_rows->takeAt(0)) {
        if (QWidget* w = item->widget()) {
            w->hide();
            w->deleteLater(); // one of its spin boxes may be emitting now
        }
        delete item;
    }
    m_spins.clear();
    m_types = types;
    const int count = int(types.size());
    for (int i = 0; i < count; ++i) {
        auto* row = new QWidget(this);
        auto* h = new QHBoxLayout(row);
        h->setContentsMargins(0, 0, 0, 0);
        auto* title = new QLabel(operationTitle(types[std::size_t(i)]), row);
        title->setMinimumWidth(56);
        h->addWidget(title);
        const auto specs = operationSpecs(types[std::size_t(i)]);
        QDoubleSpinBox* spins[2] = {nullptr, nullptr};
        const ParameterSpec* s[2] = {&specs.first, &specs.second};
        for (int p = 0; p < 2; ++p) {
            if (!s[p]->name)
                continue;
            h->addWidget(new QLabel(Text::tr(s[p]->name), row));
            auto* spin = new QDoubleSpinBox(row);
            spin->setRange(s[p]->min, s[p]->max);
            spin->setSingleStep(s[p]->step);
            spin->setDecimals(s[p]->decimals);
            spin->setToolTip(Text::tr(s[p]->tip) + Text::tr(" (keyed)"));
            spin->setKeyboardTracking(false); // typing "0.35" is one edit, not four
            spin->setObjectName(QStringLiteral("highlightOperation%1%2").arg(i).arg(p == 0 ? 'a' : 'b'));
            // Wide enough for its longest value ("-360.0"): squeezed, a spin box cuts its number.
            spin->setMinimumWidth(spin->minimumSizeHint().width());
            spin->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
            GestureTracker::track(spin, m_document);
            h->addWidget(spin, 1);
            connect(spin, qOverload<double>(&QDoubleSpinBox::valueChanged), this, [this, spin, i, p](double v) {
                const model::HighlightTrack* track = m_document->data().highlight(m_layer);
                if (!track)
                    return;
                const int frame = m_document->currentFrame();
                algo::HighlightLayer layer = track->layerAt(frame);
                if (i >= int(layer.shape.operations.size()))
                    return;
                auto& op = layer.shape.operations[std::size_t(i)];
                (p == 0 ? op.a : op.b) = float(v);
                run([&] { m_document->highlights().setHighlightKey(m_layer, frame, layer, GestureTracker::of(spin)); });
            });
            spins[p] = spin;
        }
        if (!spins[1])
            h->addStretch(1);
        auto addButton = [&](Qt::ArrowType arrow, const QString& text, const QString& tip, bool enabled) {
            auto* b = new QToolButton(row);
            if (arrow != Qt::NoArrow)
                b->setArrowType(arrow);
            else
                b->setText(text);
            b->setToolTip(tip);
            b->setEnabled(enabled);
            h->addWidget(b);
            return b;
        };
        connect(addButton(Qt::UpArrow, {}, Text::tr("Move the operation earlier"), i > 0), &QToolButton::clicked, this,
            [this, i] { run([&] { m_document->highlights().moveHighlightOperation(m_layer, i, -1); }); });
        connect(addButton(Qt::DownArrow, {}, Text::tr("Move the operation later"), i + 1 < count),
            &QToolButton::clicked, this,
            [this, i] { run([&] { m_document->highlights().moveHighlightOperation(m_layer, i, 1); }); });
        connect(addButton(Qt::NoArrow, Text::tr("✕"), Text::tr("Remove the operation from every key"), true),
            &QToolButton::clicked, this,
            [this, i] { run([&] { m_document->highlights().removeHighlightOperation(m_layer, i); }); });
        m_rows->addWidget(row);
        row->show(); // the layout would show it only once the event loop runs
        m_spins.emplace_back(spins[0], spins[1]);
    }
}

void HighlightOperationsBox::showLayer(model::ObjectId layerId)
{
    m_layer = layerId;
    const model::HighlightTrack* track = m_document->data().highlight(layerId);
    setEnabled(track != nullptr);
    const algo::HighlightLayer layer = track ? track->layerAt(m_document->currentFrame()) : algo::HighlightLayer{};
    std::vector<algo::HighlightOperationType> types;
    for (const auto& op : layer.shape.operations)
        types.push_back(op.type);
    if (types != m_types)
        rebuildRows(types);
    for (std::size_t i = 0; i < m_spins.size(); ++i) {
        const auto& op = layer.shape.operations[i];
        if (QDoubleSpinBox* a = m_spins[i].first) {
            const QSignalBlocker block(a);
            a->setValue(op.a);
        }
        if (QDoubleSpinBox* b = m_spins[i].second) {
            const QSignalBlocker block(b);
            b->setValue(op.b);
        }
    }
}

} // namespace celform::views
