#include "render/chart_canvas.h"

#include <vtkAxis.h>
#include <vtkContextActor.h>
#include <vtkContextScene.h>
#include <vtkRenderer.h>
#include <vtkRendererCollection.h>
#include <vtkSmartPointer.h>
#include <vtkTextProperty.h>

#include "core/error.h"
#include "render/offscreen_context_impl.h"
#include "render/window_image.h"

namespace maxillo::render {

RgbImage render_chart_item(vtkChart& chart, const ChartSettings& settings) {
  OffscreenContext context(settings.size);
  auto& window = *context.impl().window;

  auto actor = vtkSmartPointer<vtkContextActor>::New();
  actor->GetScene()->AddItem(&chart);  // the chart sizes itself to the scene (AutoSize)
  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  renderer->SetBackground(settings.background.r, settings.background.g, settings.background.b);
  renderer->AddActor(actor);
  window.AddRenderer(renderer);

  window.Render();
  RgbImage image = grab_window(window);
  window.GetRenderers()->RemoveAllItems();
  if (image.width != settings.size.width || image.height != settings.size.height)
    throw Error(ErrorCode::kRenderFailed, "OSMesa", "read back a chart image of the wrong size");
  return image;
}

void style_axis_text(vtkChart& chart, int axis_id, const std::string& title, const ChartSettings& settings) {
  vtkAxis* axis = chart.GetAxis(axis_id);
  axis->SetTitle(title);
  axis->GetTitleProperties()->SetFontSize(settings.font_size);
  axis->GetTitleProperties()->SetColor(0, 0, 0);
  axis->GetTitleProperties()->BoldOff();
  axis->GetLabelProperties()->SetFontSize(settings.font_size * 4 / 5);
  axis->GetLabelProperties()->SetColor(0, 0, 0);
}

}  // namespace maxillo::render
