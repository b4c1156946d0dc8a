// The parameters a reader may change on a step, one row per control key of the step-key table
// (lesson/step_keys.h): its type gives the widget (spin box, combo box, check box, text field), its range,
// label and tooltip come from the table, and an edit is parsed by the same code as a lesson file, so the
// panel cannot offer a value a lesson could not write. A step lists the keys it offers (`controls:`); a
// reader's own scene offers every key a solve uses. Changes apply after a short pause, so that dragging a
// value does not start a computation per tick.
#pragma once

#include <QString>
#include <QWidget>
#include <vector>

#include "lesson/lesson.h"
#include "lesson/step_keys.h"

class QComboBox;
class QDoubleSpinBox;
class QGridLayout;
class QLabel;
class QPushButton;
class QTimer;

namespace rt::app {

// Appends every registered form-factor method to `box`, each with its description as the item's tooltip.
void addFormFactorMethodItems(QComboBox* box);

class ParameterPanel : public QWidget {
  Q_OBJECT
 public:
  explicit ParameterPanel(QWidget* parent = nullptr);

  // `controls`: keys as in the lesson format; `allowAll` offers every key a solve uses (a reader's scene).
  // `surfaces`: name and the scene's own reflectance (shown while the reader has not changed it).
  void setStep(const lesson::StepParameters& parameters, const std::vector<std::string>& controls,
               bool allowAll, const std::vector<std::pair<QString, Rgb>>& surfaces);
  const lesson::StepParameters& parameters() const { return parameters_; }
  // Shows `parameters` in the offered rows without emitting anything (undo, redo, a restored session); the
  // step's own values stay what "Reset" returns to.
  void showParameters(const lesson::StepParameters& parameters);
  // Emits parametersChanged now instead of after the pause (the Enter key, tests).
  void applyNow();
  bool anyEnabled() const { return anyEnabled_; }
  // The widget that edits `key` ("reflectance" is the red channel's box), for the tests that drive it as a
  // reader would; null for a key the panel has no row for.
  QWidget* editor(const std::string& key) const;
  // Whether the row of `key` is shown and can be edited.
  bool offers(const std::string& key) const;
  // The message of the last edit that was refused (empty when it was taken).
  QString lastRefusal() const { return refusal_; }

 signals:
  void parametersChanged(const lesson::StepParameters& parameters);

 private:
  struct Row {
    const lesson::StepKey* key = nullptr;
    QWidget* editor = nullptr;
    bool offered = false;
  };

  void addRow(const lesson::StepKey& key);
  void fillWidgets();
  void showValue(const Row& row);
  // An edit of `row` by the reader: parsed through the table into parameters_, then applied after the pause.
  void edited(const Row& row);
  void editedReflectance();
  QString widgetText(const Row& row) const;
  Rgb sceneReflectance(const std::string& surface) const;
  void showSurfaceReflectance();

  lesson::StepParameters original_;
  lesson::StepParameters parameters_;
  bool anyEnabled_ = false;
  bool loading_ = false;  // widgets are being filled from parameters_: their signals are not edits
  QString refusal_;
  std::vector<std::pair<QString, Rgb>> surfaces_;
  std::vector<Row> rows_;
  QGridLayout* form_ = nullptr;
  QComboBox* surface_ = nullptr;
  QWidget* rhoRow_ = nullptr;
  QDoubleSpinBox* rho_[3] = {nullptr, nullptr, nullptr};
  QPushButton* reset_ = nullptr;
  QLabel* hint_ = nullptr;
  QTimer* debounce_ = nullptr;
};

}  // namespace rt::app
