// Paints a Drawing with vtkContext2D: the same calls render to OpenGL (PNG) and to the SVG/PDF context
// devices.
#include <vtkAbstractMapper.h>
#include <vtkBrush.h>
#include <vtkCellArray.h>
#include <vtkContext2D.h>
#include <vtkContextActor.h>
#include <vtkContextDevice2D.h>
#include <vtkContextItem.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkImageData.h>
#include <vtkObjectFactory.h>
#include <vtkPen.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkRect.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkStdString.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "viz/drawing.h"
#include "viz/drawing_images.h"
#include "viz/vtk_render.h"
#include "viz/vtk_views.h"

namespace rt::viz {
namespace {

class DrawingItem : public vtkContextItem {
 public:
  static DrawingItem* New();
  vtkTypeMacro(DrawingItem, vtkContextItem) void setDrawing(Drawing drawing) {
    drawing_ = std::move(drawing);
  }

  bool Paint(vtkContext2D* painter) override {
    // Fitted to the scene (the app's window may differ from the figure size), centred, fonts scaled alike.
    double scale = 1.0;
    Vec2 offset = Vec2::Zero();
    if (vtkContextScene* scene = GetScene();
        scene && scene->GetSceneWidth() > 0 && scene->GetSceneHeight() > 0) {
      scale = std::min(scene->GetSceneWidth() / drawing_.width, scene->GetSceneHeight() / drawing_.height);
      offset = 0.5 * Vec2(scene->GetSceneWidth() - scale * drawing_.width,
                          scene->GetSceneHeight() - scale * drawing_.height);
    }
    std::vector<float> xy;
    // The screen's device fills runs of plain polygons in one batch (a hemicube's thousands of pixels cost
    // one draw call, not one each); the SVG and PDF devices get them one by one, as before.
    const bool batch = painter->GetDevice() && painter->GetDevice()->IsA("vtkOpenGLContextDevice2D");
    PolygonBatch polygons;
    for (Drawing::Shape shape : drawing_.shapes) {
      if (batch && shape.kind == Drawing::Kind::Polygon && shape.strokeWidth <= 0 &&
          shape.points.size() >= 3) {
        polygons.add(shape, scale, offset);
        continue;
      }
      polygons.draw(painter);
      xy.clear();
      for (const Vec2& p : shape.points) {
        xy.push_back(static_cast<float>(offset.x() + scale * p.x()));
        xy.push_back(static_cast<float>(offset.y() + scale * p.y()));
      }
      shape.fontSize *= scale;
      shape.strokeWidth *= scale;
      const int n = static_cast<int>(shape.points.size());
      switch (shape.kind) {
        case Drawing::Kind::Polygon:
          if (n < 3) break;
          painter->GetPen()->SetLineType(vtkPen::NO_PEN);
          painter->GetBrush()->SetColor(shape.fill[0], shape.fill[1], shape.fill[2], 255);
          painter->DrawPolygon(xy.data(), n);
          if (shape.strokeWidth > 0) {
            xy.push_back(xy[0]);
            xy.push_back(xy[1]);
            strokePen(painter, shape);
            painter->DrawPoly(xy.data(), n + 1);
          }
          break;
        case Drawing::Kind::Polyline:
          if (n < 2 || shape.strokeWidth <= 0) break;
          strokePen(painter, shape);
          painter->DrawPoly(xy.data(), n);
          break;
        case Drawing::Kind::Text: {
          if (n < 1 || shape.text.empty()) break;
          vtkTextProperty* text = painter->GetTextProp();
          text->SetFontFamilyToArial();
          text->SetFontSize(static_cast<int>(shape.fontSize + 0.5));
          text->SetColor(shape.fill[0] / 255.0, shape.fill[1] / 255.0, shape.fill[2] / 255.0);
          text->SetBold(shape.bold);
          text->SetItalic(false);
          text->SetShadow(false);
          text->SetOrientation(shape.angleDegrees);
          text->SetJustification(shape.hAlign == Drawing::Align::Start    ? VTK_TEXT_LEFT
                                 : shape.hAlign == Drawing::Align::Centre ? VTK_TEXT_CENTERED
                                                                          : VTK_TEXT_RIGHT);
          text->SetVerticalJustification(shape.vAlign == Drawing::Align::Start    ? VTK_TEXT_BOTTOM
                                         : shape.vAlign == Drawing::Align::Centre ? VTK_TEXT_CENTERED
                                                                                  : VTK_TEXT_TOP);
          painter->DrawString(xy[0], xy[1], vtkStdString(shape.text));
          break;
        }
        case Drawing::Kind::Image:
          if (n < 2 || shape.pixelsWide <= 0 || shape.pixelsHigh <= 0) break;
          drawImage(painter, shape, xy);
          break;
      }
    }
    polygons.draw(painter);
    return true;
  }

 private:
  // Filled polygons without outline, as one polydata with a colour per cell (drawn as the device draws one
  // polygon: a fan of triangles).
  class PolygonBatch {
   public:
    void add(const Drawing::Shape& shape, double scale, const Vec2& offset) {
      if (!points_) {
        points_ = vtkSmartPointer<vtkPoints>::New();
        cells_ = vtkSmartPointer<vtkCellArray>::New();
        colours_ = vtkSmartPointer<vtkUnsignedCharArray>::New();
        colours_->SetNumberOfComponents(4);
      }
      cells_->InsertNextCell(static_cast<int>(shape.points.size()));
      for (const Vec2& p : shape.points)
        cells_->InsertCellPoint(
            points_->InsertNextPoint(offset.x() + scale * p.x(), offset.y() + scale * p.y(), 0.0));
      const unsigned char colour[4] = {shape.fill[0], shape.fill[1], shape.fill[2], 255};
      colours_->InsertNextTypedTuple(colour);
    }
    void draw(vtkContext2D* painter) {
      if (!points_) return;
      auto polygons = vtkSmartPointer<vtkPolyData>::New();
      polygons->SetPoints(points_);
      polygons->SetPolys(cells_);
      painter->DrawPolyData(0.0f, 0.0f, polygons, colours_, VTK_SCALAR_MODE_USE_CELL_DATA);
      points_ = nullptr;
      cells_ = nullptr;
      colours_ = nullptr;
    }

   private:
    vtkSmartPointer<vtkPoints> points_;
    vtkSmartPointer<vtkCellArray> cells_;
    vtkSmartPointer<vtkUnsignedCharArray> colours_;
  };

  // Pixels as an RGB texture, stretched over the shape's rectangle.
  static void drawImage(vtkContext2D* painter, const Drawing::Shape& shape, const std::vector<float>& xy) {
    painter->DrawImage(vtkRectf(xy[0], xy[1], xy[2] - xy[0], xy[3] - xy[1]), imageDataOf(shape));
  }
  static void strokePen(vtkContext2D* painter, const Drawing::Shape& shape) {
    painter->GetPen()->SetLineType(vtkPen::SOLID_LINE);
    painter->GetPen()->SetColor(shape.stroke[0], shape.stroke[1], shape.stroke[2], 255);
    painter->GetPen()->SetWidth(static_cast<float>(shape.strokeWidth));
  }
  Drawing drawing_;
};
vtkStandardNewMacro(DrawingItem);

}  // namespace

vtkSmartPointer<vtkRenderer> makeDrawingRenderer(const Drawing& drawing) {
  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  renderer->SetBackground(drawing.background[0] / 255.0, drawing.background[1] / 255.0,
                          drawing.background[2] / 255.0);
  auto actor = vtkSmartPointer<vtkContextActor>::New();
  auto item = vtkSmartPointer<DrawingItem>::New();
  item->setDrawing(drawing);
  actor->GetScene()->AddItem(item);
  renderer->AddActor(actor);
  return renderer;
}

void writeDrawing(const Drawing& drawing, const std::string& path) {
  figureFormatOf(path);
  auto view = vtkSmartPointer<vtkContextView>::New();
  view->SetRenderWindow(
      makeOffscreenWindow(static_cast<int>(drawing.width), static_cast<int>(drawing.height)));
  view->GetRenderer()->SetBackground(drawing.background[0] / 255.0, drawing.background[1] / 255.0,
                                     drawing.background[2] / 255.0);
  auto item = vtkSmartPointer<DrawingItem>::New();
  item->setDrawing(drawing);
  view->GetScene()->AddItem(item);
  // The figure's words, in drawing order (the first is its title where it has one).
  std::string title, words;
  for (const Drawing::Shape& shape : drawing.shapes) {
    if (shape.kind != Drawing::Kind::Text || shape.text.empty()) continue;
    if (title.empty()) title = shape.text;
    words += (words.empty() ? "" : " | ") + shape.text;
  }
  writeContextView(view, path, title, words, [&drawing](std::string& svg) {
    if (drawing.count(Drawing::Kind::Image) > 0) embedDrawingImages(svg, drawing);
  });
}

}  // namespace rt::viz
