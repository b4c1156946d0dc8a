#include "app/parameter_panel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QTimer>
#include <algorithm>
#include <climits>
#include <cmath>

#include "core/formfactor/formfactor_method.h"
#include "core/input_error.h"

namespace rt::app {
namespace {

using lesson::KeyType;
using lesson::StepKey;

bool listed(const std::vector<std::string>& controls, const std::string& key) {
  return std::find(controls.begin(), controls.end(), key) != controls.end();
}

// Rows shown (disabled) even where a step does not offer them: what any step computes with.
bool alwaysShown(const std::string& key) {
  for (const char* k :
       {"method", "resolution", "samples", "subdivide", "solver", "iterations", "light-scale"})
    if (key == k) return true;
  return false;
}

// Shows or hides a row: its label and its field. (A grid, not a QFormLayout: Qt 6.4's form layout writes past
// a buffer when it lays out hidden rows.)
void setRowShown(QGridLayout* grid, QWidget* field, bool shown) {
  const int index = grid->indexOf(field);
  if (index < 0) return;
  int row = 0, column = 0, rowSpan = 0, columnSpan = 0;
  grid->getItemPosition(index, &row, &column, &rowSpan, &columnSpan);
  if (QLayoutItem* label = grid->itemAtPosition(row, 0); label && label->widget() && label->widget() != field)
    label->widget()->setVisible(shown);
  field->setVisible(shown);
}

void addGridRow(QGridLayout* grid, const QString& label, QWidget* field) {
  const int row = grid->rowCount();
  auto* text = new QLabel(label, field->parentWidget());
  text->setBuddy(field);
  // A long label ("Hemicube resolution") takes two lines in a narrow panel rather than pushing its field
  // out of sight on a 1024-pixel projector.
  text->setWordWrap(true);
  grid->addWidget(text, row, 0);
  grid->addWidget(field, row, 1);
}

int clampToInt(double v) {
  return static_cast<int>(std::clamp(v, static_cast<double>(INT_MIN), static_cast<double>(INT_MAX)));
}

}  // namespace

void addFormFactorMethodItems(QComboBox* box) {
  // Each method says what it computes when the pointer rests on it.
  for (const auto& name : formFactorMethodNames()) {
    box->addItem(QString::fromStdString(name));
    try {
      box->setItemData(box->count() - 1, QString::fromStdString(makeFormFactorMethod(name)->description()),
                       Qt::ToolTipRole);
    } catch (const std::exception&) {
      // A factory that fails is reported when the method is used, not here.
    }
  }
}

ParameterPanel::ParameterPanel(QWidget* parent) : QWidget(parent) {
  form_ = new QGridLayout(this);
  form_->setColumnStretch(1, 1);
  debounce_ = new QTimer(this);
  debounce_->setSingleShot(true);
  debounce_->setInterval(350);
  connect(debounce_, &QTimer::timeout, this, &ParameterPanel::applyNow);
  for (const StepKey& key : lesson::stepKeyTable())
    if (key.control) addRow(key);
  reset_ = new QPushButton(tr("Reset to the step's values"), this);
  hint_ = new QLabel(this);
  hint_->setWordWrap(true);
  form_->addWidget(reset_, form_->rowCount(), 0, 1, 2);
  form_->addWidget(hint_, form_->rowCount(), 0, 1, 2);
  connect(reset_, &QPushButton::clicked, this, [this] {
    parameters_ = original_;
    fillWidgets();
    applyNow();
  });
}

void ParameterPanel::addRow(const StepKey& key) {
  const QString label = QString::fromStdString(key.label);
  const QString tip = QString::fromStdString(key.tooltip);
  rows_.push_back({&key, nullptr, false});
  const std::size_t index = rows_.size() - 1;
  auto changed = [this, index] { edited(rows_[index]); };
  QWidget* editor = nullptr;
  if (key.name == "reflectance") {
    // A surface, then its three channels: the surface picks which override the boxes edit.
    surface_ = new QComboBox(this);
    surface_->setToolTip(tr("The surface whose reflectance the boxes below change"));
    addGridRow(form_, tr("Surface"), surface_);
    rhoRow_ = new QWidget(this);
    auto* layout = new QHBoxLayout(rhoRow_);
    layout->setContentsMargins(0, 0, 0, 0);
    for (auto*& spin : rho_) {
      spin = new QDoubleSpinBox(rhoRow_);
      spin->setRange(key.min, std::min(key.max, 0.999));
      spin->setSingleStep(key.step);
      spin->setDecimals(key.decimals);
      spin->setToolTip(tip);
      layout->addWidget(spin);
      connect(spin, &QDoubleSpinBox::valueChanged, this, [this] { editedReflectance(); });
    }
    connect(surface_, &QComboBox::currentTextChanged, this, [this] { showSurfaceReflectance(); });
    editor = rhoRow_;
  } else if (key.type == KeyType::Int) {
    auto* spin = new QSpinBox(this);
    spin->setRange(clampToInt(key.min), clampToInt(key.max));
    spin->setSingleStep(static_cast<int>(std::max(1.0, key.step)));
    if (!key.zeroText.empty()) spin->setSpecialValueText(tr(key.zeroText.c_str()));
    connect(spin, &QSpinBox::valueChanged, this, changed);
    editor = spin;
  } else if (key.type == KeyType::Double && !key.logScale) {
    auto* spin = new QDoubleSpinBox(this);
    spin->setRange(key.min, std::min(key.max, 1e6));
    spin->setDecimals(key.decimals);
    spin->setSingleStep(key.step);
    if (!key.zeroText.empty()) spin->setSpecialValueText(tr(key.zeroText.c_str()));
    connect(spin, &QDoubleSpinBox::valueChanged, this, changed);
    editor = spin;
  } else if (key.type == KeyType::Bool) {
    auto* box = new QCheckBox(this);
    connect(box, &QCheckBox::toggled, this, changed);
    editor = box;
  } else if (key.type == KeyType::Choice) {
    auto* box = new QComboBox(this);
    if (key.name == "method")
      addFormFactorMethodItems(box);
    else
      for (const auto& v : key.allowed()) box->addItem(QString::fromStdString(v));
    box->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    box->setMinimumContentsLength(8);
    connect(box, &QComboBox::currentTextChanged, this, changed);
    editor = box;
  } else {
    // Tolerances (decades apart) and names are typed; Enter or leaving the field applies them.
    auto* line = new QLineEdit(this);
    // 0 shows as the choice it stands for (an empty field with that text greyed), not as a tolerance of 0.
    if (!key.zeroText.empty()) line->setPlaceholderText(tr(key.zeroText.c_str()));
    connect(line, &QLineEdit::editingFinished, this, changed);
    editor = line;
  }
  editor->setToolTip(tip);
  editor->setObjectName(QString::fromStdString("control-" + key.name));
  rows_[index].editor = editor;
  addGridRow(form_, label, editor);
}

QWidget* ParameterPanel::editor(const std::string& key) const {
  const StepKey* row = lesson::findStepKey(key);
  if (row && row->name == "reflectance") return rho_[0];
  for (const Row& r : rows_)
    if (r.key == row) return r.editor;
  return nullptr;
}

bool ParameterPanel::offers(const std::string& key) const {
  const StepKey* row = lesson::findStepKey(key);
  for (const Row& r : rows_)
    if (r.key == row) return r.offered && r.editor->isEnabled();
  return false;
}

void ParameterPanel::setStep(const lesson::StepParameters& parameters,
                             const std::vector<std::string>& controls, bool allowAll,
                             const std::vector<std::pair<QString, Rgb>>& surfaces) {
  debounce_->stop();
  loading_ = true;
  original_ = parameters;
  parameters_ = parameters;
  surfaces_ = surfaces;
  refusal_.clear();
  const bool anyReflectance = allowAll || listed(controls, "reflectance");
  surface_->clear();
  for (const auto& [name, rho] : surfaces)
    if (anyReflectance || listed(controls, "reflectance." + name.toStdString())) surface_->addItem(name);
  anyEnabled_ = false;
  for (Row& row : rows_) {
    const StepKey& key = *row.key;
    if (key.name == "reflectance") {
      row.offered = surface_->count() > 0;
      setRowShown(form_, surface_, row.offered || alwaysShown(key.name));
    } else {
      row.offered = allowAll ? key.acceptedBy(lesson::Stage::Solve) : listed(controls, key.name);
    }
    row.editor->setEnabled(row.offered);
    setRowShown(form_, row.editor, row.offered || alwaysShown(key.name));
    anyEnabled_ |= row.offered;
  }
  surface_->setEnabled(surface_->count() > 0);
  reset_->setEnabled(anyEnabled_);
  hint_->setText(anyEnabled_
                     ? tr("Changes apply after a short pause. A change of light or reflectance re-solves "
                          "without recomputing the form factors.")
                     : tr("This step has no parameters to change."));
  fillWidgets();
  loading_ = false;
}

void ParameterPanel::showParameters(const lesson::StepParameters& parameters) {
  debounce_->stop();
  parameters_ = parameters;
  refusal_.clear();
  const bool wasLoading = loading_;
  loading_ = true;
  // Rows the step does not offer keep showing what the step used (setStep).
  for (const Row& row : rows_)
    if (row.offered) showValue(row);
  showSurfaceReflectance();
  loading_ = wasLoading;
}

void ParameterPanel::fillWidgets() {
  const bool wasLoading = loading_;
  loading_ = true;
  for (const Row& row : rows_) showValue(row);
  showSurfaceReflectance();
  loading_ = wasLoading;
}

// The widget shows the step's value, or the default the method or solver then uses.
void ParameterPanel::showValue(const Row& row) {
  const StepKey& key = *row.key;
  if (key.name == "reflectance") return;
  const std::string value = lesson::stepValueText(parameters_, key, key.name).value_or(key.defaultText);
  const QString text = QString::fromStdString(value);
  if (auto* spin = qobject_cast<QSpinBox*>(row.editor)) {
    // Through a double: values from a million up are written in exponent form ("1.6e+07"), which toInt()
    // reads as 0, the "automatic" of the ray budgets.
    spin->setValue(clampToInt(std::round(text.toDouble())));
  } else if (auto* spin = qobject_cast<QDoubleSpinBox*>(row.editor)) {
    spin->setValue(text.toDouble());
  } else if (auto* box = qobject_cast<QCheckBox*>(row.editor)) {
    box->setChecked(value == "true");
  } else if (auto* box = qobject_cast<QComboBox*>(row.editor)) {
    const int i = box->findText(text);
    if (i >= 0) box->setCurrentIndex(i);
  } else if (auto* line = qobject_cast<QLineEdit*>(row.editor)) {
    bool number = false;
    const double v = text.toDouble(&number);
    line->setText(!key.zeroText.empty() && number && v == 0 ? QString() : text);
  }
}

QString ParameterPanel::widgetText(const Row& row) const {
  if (auto* spin = qobject_cast<QSpinBox*>(row.editor)) return QString::number(spin->value());
  if (auto* spin = qobject_cast<QDoubleSpinBox*>(row.editor)) return QString::number(spin->value(), 'g', 12);
  if (auto* box = qobject_cast<QCheckBox*>(row.editor)) return box->isChecked() ? "true" : "false";
  if (auto* box = qobject_cast<QComboBox*>(row.editor)) return box->currentText();
  if (auto* line = qobject_cast<QLineEdit*>(row.editor)) return line->text().trimmed();
  return {};
}

void ParameterPanel::edited(const Row& row) {
  if (loading_ || !row.offered) return;
  const StepKey& key = *row.key;
  const std::string text = widgetText(row).toStdString();
  // An emptied text field returns to the step's value.
  if (text.empty() && qobject_cast<QLineEdit*>(row.editor)) {
    loading_ = true;
    showValue(row);
    loading_ = false;
    return;
  }
  lesson::StepParameters next = parameters_;
  try {
    lesson::applyStepValue(next, key, key.name, text, {"the parameter panel"});
  } catch (const InputError& e) {
    refusal_ = QString::fromStdString(e.message());
    hint_->setText(tr("Not applied: %1").arg(refusal_));
    return;
  }
  refusal_.clear();
  // The two ways of meshing exclude each other: the one the reader touched wins.
  if (key.name == "subdivide") next.maxEdge.reset();
  if (key.name == "max-edge") next.subdivide.reset();
  if (stepValueText(next, key, key.name) == stepValueText(parameters_, key, key.name)) return;
  parameters_ = next;
  debounce_->start();
}

Rgb ParameterPanel::sceneReflectance(const std::string& surface) const {
  for (const auto& [name, rho] : surfaces_)
    if (name.toStdString() == surface) return rho;
  return Rgb::Zero();
}

void ParameterPanel::showSurfaceReflectance() {
  const bool wasLoading = loading_;
  loading_ = true;
  const std::string surface = surface_->currentText().toStdString();
  auto it = parameters_.reflectance.find(surface);
  const Rgb rho = it != parameters_.reflectance.end() ? it->second : sceneReflectance(surface);
  for (int c = 0; c < 3; ++c) rho_[c]->setValue(rho[c]);
  loading_ = wasLoading;
}

void ParameterPanel::editedReflectance() {
  if (loading_ || surface_->count() == 0) return;
  const std::string surface = surface_->currentText().toStdString();
  const Rgb rho(rho_[0]->value(), rho_[1]->value(), rho_[2]->value());
  // Only a value that differs from the scene's becomes an override (keeps the step's parameters as written).
  if (parameters_.reflectance.count(surface) == 0 && (rho - sceneReflectance(surface)).isZero(1e-9)) return;
  parameters_.reflectance[surface] = rho;
  debounce_->start();
}

void ParameterPanel::applyNow() {
  debounce_->stop();
  emit parametersChanged(parameters_);
}

}  // namespace rt::app
