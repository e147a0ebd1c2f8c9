// Scene tree: rebuilt from the document when its structure changes, selection kept by id.
#include "celform/views/panels/scene_panel.h"

#include "celform/views/overlays/drawing_overlay.h"
#include "celform/views/panels/thumbnail.h"

#include <QHeaderView>
#include <QIcon>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QSignalBlocker>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace celform::views {
namespace {
constexpr int kKindRole = Qt::UserRole + 1;
constexpr int kIdRole = Qt::UserRole + 2;
/// An eye, open or shut: the drawing shown over the model or not (a desktop theme's icon when it
/// has one).
QIcon eyeIcon(bool open)
{
    const QIcon themed = QIcon::fromTheme(open ? QStringLiteral("view-visible") : QStringLiteral("view-hidden"));
    if (!themed.isNull())
        return themed;
    QPixmap pixmap(16, 16);
    pixmap.fill(Qt::transparent);
    QPainter painter(&pixmap);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(QPen(QColor(60, 60, 60), 1.4));
    QPainterPath lid;
    lid.moveTo(1.5, 8.0);
    lid.quadTo(8.0, open ? 1.0 : 13.0, 14.5, 8.0);
    if (open) {
        lid.quadTo(8.0, 15.0, 1.5, 8.0);
        painter.drawPath(lid);
        painter.setBrush(QColor(60, 60, 60));
        painter.drawEllipse(QPointF(8.0, 8.0), 2.2, 2.2);
    } else {
        painter.drawPath(lid);
    }
    return QIcon(pixmap);
}

} // namespace

ScenePanel::ScenePanel(model::Document* document, QWidget* parent)
    : QWidget(parent)
    , m_document(document)
{
    m_tree = new QTreeWidget(this);
    m_tree->setHeaderHidden(true);
    m_tree->setColumnCount(2);
    m_tree->header()->setStretchLastSection(false);
    m_tree->header()->setSectionResizeMode(0, QHeaderView::Stretch);
    m_tree->header()->setSectionResizeMode(kEyeColumn, QHeaderView::ResizeToContents);
    m_tree->setSelectionMode(QAbstractItemView::SingleSelection);
    m_tree->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed);
    m_tree->setToolTip(
        tr("The base model, the reference drawings and the key viewpoints of the project.\n"
           "Double-click or press F2 to rename; Delete removes; the check box disables a key; the eye shows or "
           "hides a drawing over the model (D)."));
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_tree);

    connect(m_tree, &QTreeWidget::itemSelectionChanged, this, [this] {
        if (!m_rebuilding)
            emit selectionChanged(selection());
    });
    connect(m_tree, &QTreeWidget::itemChanged, this, &ScenePanel::onItemChanged);
    // The eyes take their clicks before the tree: showing a drawing does not select it.
    m_tree->viewport()->installEventFilter(this);
    connect(m_document, &model::Document::changed, this, &ScenePanel::documentChanged);
    rebuild();
}

ScenePanel::Selection ScenePanel::selection() const
{
    const auto items = m_tree->selectedItems();
    if (items.isEmpty())
        return {};
    const QTreeWidgetItem* item = items.front();
    return {ItemKind(item->data(0, kKindRole).toInt()), model::ObjectId(item->data(0, kIdRole).toULongLong())};
}

void ScenePanel::select(Selection wanted)
{
    if (wanted.kind == ItemKind::None) {
        m_tree->clearSelection();
        return;
    }
    for (QTreeWidgetItemIterator it(m_tree); *it; ++it) {
        const Selection s{
            ItemKind((*it)->data(0, kKindRole).toInt()), model::ObjectId((*it)->data(0, kIdRole).toULongLong())};
        if (s == wanted) {
            m_tree->setCurrentItem(*it);
            return;
        }
    }
    m_tree->clearSelection();
}

void ScenePanel::setDrawingOverlay(DrawingOverlay* overlay)
{
    m_overlay = overlay;
    connect(overlay, &DrawingOverlay::drawingChanged, this, &ScenePanel::updateEyes);
    updateEyes();
}

bool ScenePanel::eventFilter(QObject* watched, QEvent* event)
{
    const QEvent::Type type = event->type();
    if (watched != m_tree->viewport() || !m_overlay
        || (type != QEvent::MouseButtonPress && type != QEvent::MouseButtonDblClick
            && type != QEvent::MouseButtonRelease))
        return QWidget::eventFilter(watched, event);
    const auto* mouse = static_cast<QMouseEvent*>(event);
    const QModelIndex index = m_tree->indexAt(mouse->position().toPoint());
    QTreeWidgetItem* item = m_tree->itemFromIndex(index.siblingAtColumn(0));
    if (!item || index.column() != kEyeColumn || ItemKind(item->data(0, kKindRole).toInt()) != ItemKind::Drawing)
        return QWidget::eventFilter(watched, event);
    if (type != QEvent::MouseButtonRelease && mouse->button() == Qt::LeftButton)
        m_overlay->toggleShown(model::ObjectId(item->data(0, kIdRole).toULongLong()));
    return true;
}

void ScenePanel::updateEyes()
{
    if (!m_drawingsRoot)
        return;
    const model::ObjectId shown = m_overlay ? m_overlay->drawing() : 0;
    const QSignalBlocker block(m_tree);
    for (int i = 0; i < m_drawingsRoot->childCount(); ++i) {
        QTreeWidgetItem* item = m_drawingsRoot->child(i);
        const bool open = model::ObjectId(item->data(0, kIdRole).toULongLong()) == shown;
        item->setIcon(kEyeColumn, eyeIcon(open));
        item->setToolTip(kEyeColumn,
            open ? tr("Shown over the model: click to hide (D)") : tr("Hidden: click to show over the model (D)"));
    }
}

void ScenePanel::removeSelected()
{
    const Selection s = selection();
    if (s.kind == ItemKind::Drawing)
        m_document->drawings().removeDrawing(s.id);
    else if (s.kind == ItemKind::Key)
        m_document->keys().removeKey(s.id);
}

void ScenePanel::documentChanged(const model::ChangeSet& change)
{
    using model::Part;
    // Only structure rebuilds the tree (and its drawing thumbnails): a brush step or an opacity
    // drag does not touch it; a re-aligned drawing only updates its tooltip.
    if (change.reset || change.has(Part::Mesh)
        || ((change.has(Part::Drawings) || change.has(Part::Keys)) && change.structure)) {
        rebuild();
        return;
    }
    if (change.has(Part::Drawings) || (change.has(Part::Keys) && !change.offsetsOnly))
        for (const model::ObjectId id : change.ids)
            updateItem(id);
}

void ScenePanel::updateItem(model::ObjectId id)
{
    const auto& data = m_document->data();
    for (QTreeWidgetItemIterator it(m_tree); *it; ++it) {
        QTreeWidgetItem* item = *it;
        if (model::ObjectId(item->data(0, kIdRole).toULongLong()) != id)
            continue;
        const QSignalBlocker block(m_tree);
        if (const model::Drawing* d = data.drawing(id))
            item->setToolTip(0, drawingTip(*d));
        else if (const model::KeyViewpoint* k = data.key(id))
            item->setToolTip(0, keyTip(*k));
        return;
    }
}

QString ScenePanel::drawingTip(const model::Drawing& d)
{
    return tr("%1 × %2 px, %3%4")
        .arg(d.image.width())
        .arg(d.image.height())
        .arg(d.imageFormat.toUpper())
        .arg(d.aligned ? tr(", aligned") : tr(", not aligned yet"));
}

QString ScenePanel::keyTip(const model::KeyViewpoint& k)
{
    return tr("Direction (%1, %2, %3)")
        .arg(k.direction.x(), 0, 'f', 3)
        .arg(k.direction.y(), 0, 'f', 3)
        .arg(k.direction.z(), 0, 'f', 3);
}

void ScenePanel::rebuild()
{
    const Selection previous = selection();
    m_rebuilding = true;
    m_tree->clear();
    const auto& data = m_document->data();

    auto makeRoot = [this](const QString& text, const QString& tip, ItemKind kind) {
        auto* item = new QTreeWidgetItem(m_tree, {text});
        item->setToolTip(0, tip);
        item->setData(0, kKindRole, int(kind));
        item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable);
        QFont font = item->font(0);
        font.setBold(true);
        item->setFont(0, font);
        return item;
    };
    m_modelRoot = makeRoot(tr("Base model"), tr("The 3D model that the key deformations change"), ItemKind::BaseModel);
    if (data.baseMesh)
        m_modelRoot->setText(0, tr("Base model: %1").arg(data.baseMeshName));
    else
        m_modelRoot->setText(0, tr("Base model: none (File > Import Mesh)"));

    m_drawingsRoot = makeRoot(tr("Reference drawings (%1)").arg(data.drawings.size()),
        tr("The model sheet: hand-drawn views of the character"), ItemKind::None);
    for (const auto& d : data.drawings) {
        auto* item = new QTreeWidgetItem(m_drawingsRoot, {d.name});
        item->setData(0, kKindRole, int(ItemKind::Drawing));
        item->setData(0, kIdRole, QVariant::fromValue<qulonglong>(d.id));
        item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsEditable);
        item->setToolTip(0, drawingTip(d));
        if (!d.image.isNull())
            item->setIcon(0, QIcon(drawingThumbnail(d.image, QSize(32, 32))));
    }
    m_keysRoot = makeRoot(tr("Key viewpoints (%1)").arg(data.keys.size()),
        tr("Key deformations, each seen from its key viewpoint"), ItemKind::None);
    for (const auto& k : data.keys) {
        auto* item = new QTreeWidgetItem(m_keysRoot, {k.name});
        item->setData(0, kKindRole, int(ItemKind::Key));
        item->setData(0, kIdRole, QVariant::fromValue<qulonglong>(k.id));
        item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsEditable | Qt::ItemIsUserCheckable);
        item->setCheckState(0, k.enabled ? Qt::Checked : Qt::Unchecked);
        item->setToolTip(0, keyTip(k));
    }
    m_tree->expandAll();
    m_rebuilding = false;
    updateEyes();
    select(previous);
    if (!(selection() == previous))
        emit selectionChanged(selection());
}

void ScenePanel::onItemChanged(QTreeWidgetItem* item, int column)
{
    if (m_rebuilding || column != 0)
        return;
    const auto kind = ItemKind(item->data(0, kKindRole).toInt());
    const auto id = model::ObjectId(item->data(0, kIdRole).toULongLong());
    const QString name = item->text(0);
    // Defer: the document rebuilds this tree, which must not happen inside the tree's own signal.
    QMetaObject::invokeMethod(
        this,
        [this, kind, id, name, checked = item->checkState(0) == Qt::Checked] {
            if (kind == ItemKind::Drawing) {
                m_document->drawings().renameDrawing(id, name);
            } else if (kind == ItemKind::Key) {
                m_document->keys().renameKey(id, name);
                m_document->keys().setKeyEnabled(id, checked);
            }
            rebuild(); // restores the stored name when a rename was refused (empty name)
        },
        Qt::QueuedConnection);
}

} // namespace celform::views
