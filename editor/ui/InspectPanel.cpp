#include "editor/ui/InspectPanel.hpp"

#include <QHeaderView>
#include <QLabel>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace speculum::ui {

namespace {

using render::reference::HitKind;
using render::reference::PathEventKind;
using render::reference::PathVertex;

constexpr int kNodeRole = Qt::UserRole + 1;
constexpr int kVertexRole = Qt::UserRole + 2;

QString name(const render::FrameInput& input, const render::reference::PixelId& id) {
    return QString::fromStdString(render::inspect::nodeName(input, id));
}

QString colour(const glm::dvec3& c) {
    return QStringLiteral("(%1, %2, %3)").arg(c.r, 0, 'f', 3).arg(c.g, 0, 'f', 3).arg(c.b, 0, 'f', 3);
}

glm::vec4 kindColour(const PathVertex& v) {
    switch (v.kind) {
    case PathEventKind::Mirror:
    case PathEventKind::DepthLimit:
        return {0.2f, 0.9f, 1.0f, 1.0f};
    case PathEventKind::Reflector:
    case PathEventKind::LostBelow:
        return {1.0f, 0.3f, 0.9f, 1.0f};
    case PathEventKind::Background:
        return {0.6f, 0.6f, 0.6f, 1.0f};
    case PathEventKind::Surface:
        return {1.0f, 0.9f, 0.2f, 1.0f};
    }
    return glm::vec4(1.0f);
}

void addShadowRays(const PathVertex& v, const render::FrameInput& input,
                   std::vector<render::GuideLine>& lines) {
    for (const render::reference::LightTerm& t : v.shading.lights) {
        if (!t.shadowed || t.nDotL <= 0.0 || std::size_t(t.light) >= input.lights.size())
            continue;
        const render::Light& light = input.lights[std::size_t(t.light)];
        const glm::dvec3 to = light.type == render::LightType::Directional
                                  ? v.position - light.direction * 3.0
                                  : light.position;
        const glm::vec4 c =
            t.visibility > 0.0 ? glm::vec4(0.3f, 1.0f, 0.3f, 0.9f) : glm::vec4(1.0f, 0.25f, 0.2f, 0.9f);
        lines.push_back({v.position, to, c, 1.5f, 0.25f});
    }
}

} // namespace

std::vector<render::GuideLine> pathGuides(const render::inspect::PixelExplanation& e,
                                          const render::FrameInput& input, int highlighted) {
    std::vector<render::GuideLine> lines;
    const auto& vertices = e.exact.centre.vertices;
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        const PathVertex& v = vertices[i];
        // The segment arriving at v: white from the camera, then the colour of the bounce it left.
        const glm::vec4 c = i == 0 ? glm::vec4(1.0f) : kindColour(vertices[i - 1]);
        const glm::dvec3 end = v.kind == PathEventKind::Background ? v.from + v.incoming * 3.0 : v.position;
        const bool wide = int(i) == highlighted;
        lines.push_back({v.from, end, c, wide ? 6.0f : 2.5f, wide ? 0.8f : 0.35f});
        if (v.shaded)
            addShadowRays(v, input, lines);
    }
    return lines;
}

InspectPanel::InspectPanel(QWidget* parent)
    : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    m_summary = new QLabel(tr("Turn on View ▸ Inspect Pixel and click the viewport: the exact path to that "
                              "pixel and the raster's recipe for it appear here."),
                           this);
    m_summary->setWordWrap(true);
    m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_tree = new QTreeWidget(this);
    m_tree->setObjectName(QStringLiteral("inspectTree"));
    m_tree->setHeaderLabels({tr("Step"), tr("Colour"), tr("Details")});
    m_tree->header()->setSectionResizeMode(QHeaderView::ResizeToContents);
    layout->addWidget(m_summary);
    layout->addWidget(m_tree, 1);
    connect(m_tree, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem* item) {
        const QVariant vertex = item ? item->data(0, kVertexRole) : QVariant();
        emit pathStepChosen(vertex.isValid() ? vertex.toInt() : -1);
        if (item && !item->data(0, kNodeRole).toString().isEmpty())
            emit nodeChosen(item->data(0, kNodeRole).toString());
    });
}

void InspectPanel::showMessage(const QString& message) {
    m_tree->clear();
    m_summary->setText(message);
}

void InspectPanel::show(const render::inspect::PixelExplanation& e, const render::FrameInput& input) {
    m_tree->clear();
    m_summary->setText(tr("Pixel %1,%2 — raster %3, exact %4; error (sRGB) RMS %5; %6 window PSNR %7 dB")
                           .arg(e.x)
                           .arg(e.y)
                           .arg(colour(e.rasterColour), colour(e.exactColour))
                           .arg(e.errorRms, 0, 'f', 4)
                           .arg(QStringLiteral("%1×%2").arg(e.exact.windowWidth).arg(e.exact.windowHeight))
                           .arg(e.windowPsnr, 0, 'f', 2));
    auto* exact = new QTreeWidgetItem(m_tree, {tr("Exact path"), colour(e.exactColour)});
    int index = 0;
    for (const PathVertex& v : e.exact.centre.vertices) {
        const QString node = name(input, v.hit);
        auto* item = new QTreeWidgetItem(
            exact, {QString::fromUtf8(toString(v.kind).data()) + (node.isEmpty() ? QString() : " " + node),
                    colour(v.colour),
                    v.kind == PathEventKind::Background
                        ? tr("nothing met: the background")
                        : tr("%1 m from the last point").arg(v.distance, 0, 'f', 3)});
        item->setData(0, kNodeRole, node);
        item->setData(0, kVertexRole, index++);
    }
    auto* raster = new QTreeWidgetItem(m_tree, {tr("Raster recipe"), colour(e.rasterColour)});
    for (const render::inspect::RecipeStep& s : e.recipe) {
        auto* item = new QTreeWidgetItem(
            raster, {QString::fromStdString(s.pass + (s.target.empty() ? "" : " " + s.target)),
                     s.readable ? colour(s.colour) : QString(),
                     QString::fromStdString(
                         s.what + (s.stencil >= 0 ? "; stencil " + std::to_string(s.stencil) : ""))});
        item->setToolTip(2, QString::fromStdString(s.why));
        item->setData(0, kNodeRole, QString::fromStdString(s.target));
    }
    if (e.lookup) {
        const auto& l = *e.lookup;
        const std::string text = l.layout + " map of '" + l.reflector + "', " + std::to_string(l.resolution) +
                                 "², " + l.componentLabel + ", texel (" + std::to_string(l.texelX) + ", " +
                                 std::to_string(l.texelY) + "), " + l.filter;
        auto* item = new QTreeWidgetItem(raster, {tr("map lookup"), QString(), QString::fromStdString(text)});
        item->setData(0, kNodeRole, QString::fromStdString(l.reflector));
    }
    auto* causes = new QTreeWidgetItem(m_tree, {tr("Why they differ")});
    for (const render::inspect::Cause& c : e.causes) {
        auto* item = new QTreeWidgetItem(
            causes, {QString::fromStdString(c.code), QString(), QString::fromStdString(c.text)});
        item->setToolTip(2, QString::fromStdString(c.text));
    }
    m_tree->expandAll();
}

} // namespace speculum::ui
