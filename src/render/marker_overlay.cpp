#include "render/marker_overlay.h"

#include <vtkActor2D.h>
#include <vtkCellArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper2D.h>
#include <vtkProperty2D.h>
#include <vtkRegularPolygonSource.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkTextRenderer.h>

#include <algorithm>
#include <cmath>

#include "render/label_layout.h"

namespace maxillo::render {
namespace {

constexpr ColourRGB kRimColour{0.1, 0.1, 0.1};

// Sizes follow the image so that a 512-pixel thumbnail and a 1024-pixel page read alike.
struct OverlaySizes {
  double marker_radius;
  int font_size;
};

OverlaySizes sizes_for(const int* viewport_size) {
  const double height = viewport_size[1];
  return {std::max(3.0, height / 150), std::max(9, int(std::lround(height / 64)))};
}

vtkSmartPointer<vtkTextProperty> label_style(const ColourRGB& colour, int font_size) {
  auto style = vtkSmartPointer<vtkTextProperty>::New();
  style->SetFontFamilyToArial();
  style->SetFontSize(font_size);
  style->BoldOn();
  style->SetColor(colour.r * 0.75, colour.g * 0.75, colour.b * 0.75);  // darker than the disc: legible
  style->SetBackgroundColor(1, 1, 1);
  style->SetBackgroundOpacity(0.8);
  style->SetJustificationToLeft();
  style->SetVerticalJustificationToBottom();
  return style;
}

// Extent of the text in pixels; the font's size as an estimate if FreeType cannot say.
Eigen::Vector2d text_extent(vtkTextProperty* style, const std::string& text) {
  int box[4] = {0, 0, 0, 0};
  if (vtkTextRenderer* renderer = vtkTextRenderer::GetInstance();
      renderer && renderer->GetBoundingBox(style, text, box, 72))
    return {box[1] - box[0] + 1.0, box[3] - box[2] + 1.0};
  return {0.6 * style->GetFontSize() * double(text.size()), 1.2 * style->GetFontSize()};
}

vtkSmartPointer<vtkActor2D> polygon_actor(const Eigen::Vector2d& centre, double radius, const ColourRGB& colour,
                                          bool filled) {
  auto source = vtkSmartPointer<vtkRegularPolygonSource>::New();
  source->SetNumberOfSides(24);
  source->SetCenter(centre.x(), centre.y(), 0);
  source->SetRadius(radius);
  source->SetGeneratePolygon(filled);
  source->SetGeneratePolyline(!filled);
  auto mapper = vtkSmartPointer<vtkPolyDataMapper2D>::New();
  mapper->SetInputConnection(source->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor2D>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(colour.r, colour.g, colour.b);
  actor->GetProperty()->SetLineWidth(1.5);
  return actor;
}

vtkSmartPointer<vtkActor2D> line_actor(const Eigen::Vector2d& from, const Eigen::Vector2d& to,
                                       const ColourRGB& colour) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->InsertNextPoint(from.x(), from.y(), 0);
  points->InsertNextPoint(to.x(), to.y(), 0);
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  const vtkIdType ends[2] = {0, 1};
  lines->InsertNextCell(2, ends);
  auto polydata = vtkSmartPointer<vtkPolyData>::New();
  polydata->SetPoints(points);
  polydata->SetLines(lines);
  auto mapper = vtkSmartPointer<vtkPolyDataMapper2D>::New();
  mapper->SetInputData(polydata);
  auto actor = vtkSmartPointer<vtkActor2D>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(colour.r, colour.g, colour.b);
  actor->GetProperty()->SetLineWidth(1.5);
  return actor;
}

// The point of the label's box nearest to `p`: where a leader line ends.
Eigen::Vector2d nearest_on_box(const PixelBox& box, const Eigen::Vector2d& p) {
  return p.cwiseMax(box.min).cwiseMin(box.max());
}

struct Projected {
  const SceneMarker* marker;
  Eigen::Vector2d pixel;  // viewport pixels, origin at the lower left
};

std::vector<Projected> project(vtkRenderer& renderer, std::span<const SceneMarker> markers) {
  const int* size = renderer.GetSize();
  std::vector<Projected> projected;
  for (const auto& marker : markers) {
    renderer.SetWorldPoint(marker.position.x(), marker.position.y(), marker.position.z(), 1.0);
    renderer.WorldToView();
    double view[3];
    renderer.GetViewPoint(view);
    if (std::abs(view[0]) > 1 || std::abs(view[1]) > 1 || std::abs(view[2]) > 1) continue;  // outside the view
    renderer.ViewToDisplay();
    double display[3];
    renderer.GetDisplayPoint(display);
    const int* origin = renderer.GetOrigin();
    const Eigen::Vector2d pixel(display[0] - origin[0], display[1] - origin[1]);
    if (pixel.x() < 0 || pixel.y() < 0 || pixel.x() > size[0] || pixel.y() > size[1]) continue;
    projected.push_back({&marker, pixel});
  }
  return projected;
}

}  // namespace

std::vector<vtkSmartPointer<vtkProp>> marker_props(vtkRenderer& renderer, std::span<const SceneMarker> markers) {
  const auto sizes = sizes_for(renderer.GetSize());
  const auto projected = project(renderer, markers);

  std::vector<vtkSmartPointer<vtkTextProperty>> styles;
  std::vector<LabelRequest> requests;
  for (const auto& p : projected) {
    styles.push_back(label_style(p.marker->colour, sizes.font_size));
    requests.push_back({p.pixel, text_extent(styles.back(), p.marker->label)});
  }
  const int* size = renderer.GetSize();
  const auto placed = place_labels(requests, sizes.marker_radius, Eigen::Vector2d(size[0], size[1]));

  std::vector<vtkSmartPointer<vtkProp>> props;
  // Leader lines first, discs over them, labels on top.
  for (size_t i = 0; i < projected.size(); ++i)
    if (placed[i].needs_leader)
      props.push_back(line_actor(projected[i].pixel, nearest_on_box(placed[i].box, projected[i].pixel),
                                 projected[i].marker->colour));
  for (const auto& p : projected) {
    props.push_back(polygon_actor(p.pixel, sizes.marker_radius, p.marker->colour, true));
    props.push_back(polygon_actor(p.pixel, sizes.marker_radius, kRimColour, false));
  }
  for (size_t i = 0; i < projected.size(); ++i) {
    auto text = vtkSmartPointer<vtkTextActor>::New();
    text->SetInput(projected[i].marker->label.c_str());
    text->SetTextProperty(styles[i]);
    text->SetDisplayPosition(int(std::lround(placed[i].box.min.x())), int(std::lround(placed[i].box.min.y())));
    props.push_back(text);
  }
  return props;
}

}  // namespace maxillo::render
