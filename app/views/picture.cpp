// The picture of a view kind: one view, or "all": the camera, world and NPC views side by side under
// a strip of titles (for slides, the README and the tests).
#include "app/text/catalogue.h"
#include "app/views/depth_plot.h"
#include "app/views/theme.h"
#include "app/views/views.h"

#include <stdexcept>

namespace vplab {

namespace {

using namespace draw;

constexpr int kPanelGap = 6;  // pixels between the panels of "all"

void buildView(ViewKind kind, const ViewInput& in, DisplayList& out) {
  switch (kind) {
    case ViewKind::camera: cameraView(in, out); return;
    case ViewKind::world: worldView(in, out); return;
    case ViewKind::npc: npcView(in, out); return;
    case ViewKind::morph: morphView(in, out); return;
    case ViewKind::divideFirst: out = divideFirstView(in); return;
    case ViewKind::depth: out = depthPlotView(in); return;
    case ViewKind::all: break;
  }
  throw std::logic_error("buildView: not a single view");
}

// The strip of titles over the three panels: the long titles where they fit their panel, else the
// short ones, centred over each panel.
DisplayList titleStrip(const ViewInput& in, int titleHeight) {
  const int width = in.width;
  DisplayList strip;
  strip.width = 3 * width + 2 * kPanelGap;
  strip.height = titleHeight;
  const theme::Palette& pal = theme::palette(in.settings.theme);
  strip.background = pal.stripBackground;
  strip.observer.space = Space::pixels;
  strip.antialiased = true;
  const Language lang = in.settings.language;
  const char* titles[][2] = {
      {text::Text("camera: what the synthetic camera sees (DC)").in(lang), text::Text("camera (DC)").in(lang)},
      {text::Text("world: scene, camera and view volume (WC)").in(lang), text::Text("world (WC)").in(lang)},
      {text::Text("npc: after view mapping, clipping and division (NPC)").in(lang), "NPC"}};
  std::vector<TextLabel> labels;
  for (int i = 0; i < 3; ++i) {
    const bool fits = in.text.measure(titles[i][0], TextSize::title).x <= width - 12;
    TextLabel title{{i * (width + kPanelGap) + width * 0.5, titleHeight * 0.5}, titles[i][fits ? 0 : 1], pal.text,
                    TextSize::title, Anchor::center, false};
    title.avoid = false;
    labels.push_back(title);
  }
  strip.add(Text{placeLabels(labels, in.text, strip.width, strip.height), pal.labelOutline});
  return strip;
}

}  // namespace

void buildPicture(ViewKind kind, const ViewInput& in, Picture& out) {
  if (kind != ViewKind::all) {
    out.width = in.width;
    out.height = in.height;
    out.panels.resize(1);
    out.panels[0].x = out.panels[0].y = 0;
    buildView(kind, in, out.panels[0].list);
    out.background = out.panels[0].list.background;
    return;
  }
  const int titleHeight = int(in.text.measure("Ag", TextSize::title).y) + 14;
  out.width = 3 * in.width + 2 * kPanelGap;
  out.height = titleHeight + in.height;
  out.background = theme::palette(in.settings.theme).panelGap;
  out.panels.resize(4);
  out.panels[0] = {0, 0, titleStrip(in, titleHeight)};
  const ViewKind views[3] = {ViewKind::camera, ViewKind::world, ViewKind::npc};
  for (int i = 0; i < 3; ++i) {
    Panel& p = out.panels[size_t(i) + 1];
    p.x = i * (in.width + kPanelGap);
    p.y = titleHeight;
    buildView(views[i], in, p.list);
  }
}

Picture buildPicture(ViewKind kind, const ViewInput& in) {
  Picture picture;
  buildPicture(kind, in, picture);
  return picture;
}

}  // namespace vplab
