// The parameters a reader may change on a step: form-factor method, hemicube resolution, samples,
// subdivision, solver, iterations, the reflectance of a surface and the light's intensity. A step lists the
// keys it lets the reader change (`controls:`); a user scene allows all of them. Changes are applied after a
// short pause, so that dragging a value does not start a computation per tick.
#pragma once

#include <QStringList>
#include <QWidget>

#include "lesson/lesson.h"

class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QPushButton;
class QSpinBox;
class QTimer;

namespace rt::app {

// Appends every registered form-factor method to `box`, each with its description as the item's tooltip.
void addFormFactorMethodItems(QComboBox* box);

class ParameterPanel : public QWidget {
  Q_OBJECT
 public:
  explicit ParameterPanel(QWidget* parent = nullptr);

  // `controls`: keys as in the lesson format ("method", "resolution", "samples", "subdivide", "solver",
  // "iterations", "reflectance", "reflectance.<surface>", "light-scale"); `allowAll` enables every control.
  // `surfaces`: name and the scene's own reflectance (shown while the reader has not changed it).
  void setStep(const lesson::StepParameters& parameters, const std::vector<std::string>& controls,
               bool allowAll, const std::vector<std::pair<QString, Rgb>>& surfaces);
  const lesson::StepParameters& parameters() const { return parameters_; }
  // Emits parametersChanged now instead of after the pause (tests, Enter key).
  void applyNow();
  bool anyEnabled() const { return anyEnabled_; }

  // Programmatic edits (tests, keyboard): change a value as the reader would.
  void setLightScale(double scale);
  void setReflectance(const QString& surface, double r, double g, double b);
  void setSolver(const QString& name);
  void setMethod(const QString& name);

 signals:
  void parametersChanged(const lesson::StepParameters& parameters);

 private:
  void fillWidgets();
  void readWidgets();
  Rgb sceneReflectance(const std::string& surface) const;
  void showSurfaceReflectance();
  void scheduleApply();

  lesson::StepParameters original_;
  lesson::StepParameters parameters_;
  bool anyEnabled_ = false;
  bool loading_ = false;
  std::vector<std::pair<QString, Rgb>> surfaces_;
  QComboBox* method_ = nullptr;
  QSpinBox* resolution_ = nullptr;
  QSpinBox* samples_ = nullptr;
  QSpinBox* subdivide_ = nullptr;
  QComboBox* solver_ = nullptr;
  QSpinBox* iterations_ = nullptr;
  QSpinBox* bounces_ = nullptr;
  QComboBox* surface_ = nullptr;
  QDoubleSpinBox* rho_[3] = {nullptr, nullptr, nullptr};
  QDoubleSpinBox* light_ = nullptr;
  QPushButton* reset_ = nullptr;
  QLabel* hint_ = nullptr;
  QTimer* debounce_ = nullptr;
};

}  // namespace rt::app
