// Combination rows of the Highlights dock; edits go to HighlightEdits::setHighlightCombinations.
#include "celform/views/panels/highlight_combinations.h"

#include "celform/model/document/document.h"
#include "celform/model/data/io_error.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QHBoxLayout>
#include <QPushButton>
#include <QToolButton>
#include <QVBoxLayout>

namespace celform::views {
namespace {

/// The strings keep the Highlights dock's translation context.
struct Text {
    Q_DECLARE_TR_FUNCTIONS(celform::views::HighlightPanel)
};

using Combinations = std::vector<std::pair<algo::HighlightBoolean, QString>>;

} // namespace

HighlightCombinationsBox::HighlightCombinationsBox(model::Document* document, QWidget* parent)
    : QGroupBox(Text::tr("Combinations"), parent)
    , m_document(document)
{
    auto* layout = new QVBoxLayout(this);
    m_rows = new QVBoxLayout;
    layout->addLayout(m_rows);
    m_add = new QPushButton(Text::tr("Add Combination"), this);
    m_add->setObjectName(QStringLiteral("addHighlightCombination"));
    m_add->setToolTip(
        Text::tr("Unite this layer's area with, or subtract from it, another layer's area at the same frame"));
    layout->addWidget(m_add, 0, Qt::AlignLeft);
    connect(m_add, &QPushButton::clicked, this, [this] {
        const model::HighlightTrack* track = m_document->data().highlight(m_layer);
        if (!track)
            return;
        for (const auto& other : m_document->data().look.highlights)
            if (other.id != m_layer) {
                Combinations combinations = track->combineWith;
                combinations.emplace_back(algo::HighlightBoolean::Union, other.name);
                try {
                    m_document->highlights().setHighlightCombinations(m_layer, std::move(combinations));
                } catch (const model::EditRefused&) { }
                return;
            }
    });
}

void HighlightCombinationsBox::showLayer(model::ObjectId layer)
{
    m_layer = layer;
    const auto& tracks = m_document->data().look.highlights;
    const model::HighlightTrack* track = m_document->data().highlight(layer);
    setEnabled(track != nullptr);
    m_add->setEnabled(track && tracks.size() > 1);
    QString shown = QString::number(layer);
    if (track)
        for (const auto& [mode, other] : track->combineWith)
            shown += QStringLiteral("|%1:%2").arg(int(mode)).arg(other);
    for (const auto& t : tracks)
        shown += QLatin1Char('/') + t.name;
    if (shown == m_shown)
        return;
    m_shown = shown;
    rebuildRows();
}

void HighlightCombinationsBox::rebuildRows()
{
    while (QLayoutItem* item = m_rows->takeAt(0)) {
        if (QWidget* w = item->widget()) {
            w->hide();
            w->deleteLater(); // one of its combo boxes may be emitting now
        }
        delete item;
    }
    const model::HighlightTrack* track = m_document->data().highlight(m_layer);
    if (!track)
        return;
    const auto& tracks = m_document->data().look.highlights;
    auto edit = [this](const std::function<void(Combinations&)>& change) {
        const model::HighlightTrack* t = m_document->data().highlight(m_layer);
        if (!t)
            return;
        Combinations combinations = t->combineWith;
        change(combinations);
        try {
            m_document->highlights().setHighlightCombinations(m_layer, std::move(combinations));
        } catch (const model::EditRefused&) {
            m_shown.clear();
            showLayer(m_layer);
        }
    };
    for (int i = 0; i < int(track->combineWith.size()); ++i) {
        const auto& [mode, other] = track->combineWith[std::size_t(i)];
        auto* row = new QWidget(this);
        auto* h = new QHBoxLayout(row);
        h->setContentsMargins(0, 0, 0, 0);
        auto* modeBox = new QComboBox(row);
        modeBox->addItem(Text::tr("Union with"), int(algo::HighlightBoolean::Union));
        modeBox->addItem(Text::tr("Subtract"), int(algo::HighlightBoolean::Subtraction));
        modeBox->setCurrentIndex(modeBox->findData(int(mode)));
        modeBox->setToolTip(Text::tr("Union adds the other layer's area; Subtract cuts it out of this layer's area"));
        auto* otherBox = new QComboBox(row);
        for (const auto& candidate : tracks)
            if (candidate.id != m_layer)
                otherBox->addItem(candidate.name, candidate.name);
        otherBox->setCurrentIndex(otherBox->findData(other));
        otherBox->setToolTip(Text::tr("The other layer, at the same frame"));
        auto* remove = new QToolButton(row);
        remove->setText(Text::tr("✕"));
        remove->setToolTip(Text::tr("Remove this combination"));
        h->addWidget(modeBox);
        h->addWidget(otherBox, 1);
        h->addWidget(remove);
        connect(modeBox, qOverload<int>(&QComboBox::activated), this, [edit, i, modeBox](int index) {
            const auto m = algo::HighlightBoolean(modeBox->itemData(index).toInt());
            edit([i, m](Combinations& c) {
                if (i < int(c.size()))
                    c[std::size_t(i)].first = m;
            });
        });
        connect(otherBox, qOverload<int>(&QComboBox::activated), this, [edit, i, otherBox](int index) {
            const QString name = otherBox->itemData(index).toString();
            edit([i, name](Combinations& c) {
                if (i < int(c.size()))
                    c[std::size_t(i)].second = name;
            });
        });
        connect(remove, &QToolButton::clicked, this, [edit, i] {
            edit([i](Combinations& c) {
                if (i < int(c.size()))
                    c.erase(c.begin() + i);
            });
        });
        m_rows->addWidget(row);
        row->show(); // the layout would show it only once the event loop runs
    }
}

} // namespace celform::views
