#include "app/parameter_panel.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QTimer>
#include <algorithm>

#include "core/formfactor/formfactor_method.h"
#include "core/solvers/solver.h"

namespace rt::app {
namespace {

bool allows(const std::vector<std::string>& controls, const std::string& key) {
  return std::find(controls.begin(), controls.end(), key) != controls.end();
}

QStringList toQt(const std::vector<std::string>& names) {
  QStringList list;
  for (const auto& n : names) list << QString::fromStdString(n);
  return list;
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
  auto* form = new QFormLayout(this);
  method_ = new QComboBox(this);
  addFormFactorMethodItems(method_);
  resolution_ = new QSpinBox(this);
  resolution_->setRange(4, 2048);
  samples_ = new QSpinBox(this);
  samples_->setRange(1, 65536);
  subdivide_ = new QSpinBox(this);
  subdivide_->setRange(1, 64);
  solver_ = new QComboBox(this);
  solver_->addItems(toQt(solverNames()));
  iterations_ = new QSpinBox(this);
  iterations_->setRange(1, 100000);
  bounces_ = new QSpinBox(this);
  bounces_->setRange(0, 100);
  surface_ = new QComboBox(this);
  auto* rhoRow = new QWidget(this);
  auto* rhoLayout = new QHBoxLayout(rhoRow);
  rhoLayout->setContentsMargins(0, 0, 0, 0);
  for (auto*& spin : rho_) {
    spin = new QDoubleSpinBox(rhoRow);
    spin->setRange(0.0, 0.99);
    spin->setSingleStep(0.05);
    spin->setDecimals(3);
    rhoLayout->addWidget(spin);
  }
  light_ = new QDoubleSpinBox(this);
  light_->setRange(0.0, 1000.0);
  light_->setSingleStep(0.25);
  light_->setDecimals(2);
  light_->setSuffix(QString::fromUtf8(" \u00d7"));
  resolution_->setToolTip(tr("Hemicube: pixels along the edge of the top face"));
  samples_->setToolTip(tr(
      "Ray casting: sample pairs per element pair (1 to 1024). Monte Carlo: rays per element. Hybrid: rays "
      "per 1 % of an occluded pair's form factor. Nusselt analog: segments per arc."));
  reset_ = new QPushButton(tr("Reset to the step's values"), this);
  hint_ = new QLabel(this);
  hint_->setWordWrap(true);

  form->addRow(tr("Form factors"), method_);
  form->addRow(tr("Hemicube resolution"), resolution_);
  form->addRow(tr("Samples"), samples_);
  form->addRow(tr("Subdivision (N x N)"), subdivide_);
  form->addRow(tr("Solver"), solver_);
  form->addRow(tr("Max iterations"), iterations_);
  form->addRow(tr("Bounces"), bounces_);
  form->addRow(tr("Surface"), surface_);
  form->addRow(tr("Reflectance (r g b)"), rhoRow);
  form->addRow(tr("Light intensity"), light_);
  form->addRow(reset_);
  form->addRow(hint_);

  for (QComboBox* box : {method_, solver_, surface_}) {
    box->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    box->setMinimumContentsLength(8);
  }
  debounce_ = new QTimer(this);
  debounce_->setSingleShot(true);
  debounce_->setInterval(350);
  connect(debounce_, &QTimer::timeout, this, &ParameterPanel::applyNow);
  auto changed = [this] { scheduleApply(); };
  connect(method_, &QComboBox::currentTextChanged, this, changed);
  connect(solver_, &QComboBox::currentTextChanged, this, changed);
  for (QSpinBox* s : {resolution_, samples_, subdivide_, iterations_, bounces_})
    connect(s, &QSpinBox::valueChanged, this, changed);
  for (QDoubleSpinBox* s : rho_) connect(s, &QDoubleSpinBox::valueChanged, this, changed);
  connect(light_, &QDoubleSpinBox::valueChanged, this, changed);
  connect(surface_, &QComboBox::currentTextChanged, this, [this] { showSurfaceReflectance(); });
  connect(reset_, &QPushButton::clicked, this, [this] {
    parameters_ = original_;
    fillWidgets();
    applyNow();
  });
}

void ParameterPanel::setStep(const lesson::StepParameters& parameters,
                             const std::vector<std::string>& controls, bool allowAll,
                             const std::vector<std::pair<QString, Rgb>>& surfaces) {
  debounce_->stop();
  original_ = parameters;
  parameters_ = parameters;
  surfaces_ = surfaces;
  loading_ = true;
  const bool anyReflectance = allowAll || allows(controls, "reflectance");
  surface_->clear();
  for (const auto& [name, rho] : surfaces)
    if (anyReflectance || allows(controls, "reflectance." + name.toStdString())) surface_->addItem(name);
  const auto enable = [&](QWidget* w, const std::string& key) {
    w->setEnabled(allowAll || allows(controls, key));
    return w->isEnabled();
  };
  anyEnabled_ = false;
  anyEnabled_ |= enable(method_, "method");
  anyEnabled_ |= enable(resolution_, "resolution");
  anyEnabled_ |= enable(samples_, "samples");
  anyEnabled_ |= enable(subdivide_, "subdivide");
  anyEnabled_ |= enable(solver_, "solver");
  anyEnabled_ |= enable(iterations_, "iterations");
  anyEnabled_ |= enable(bounces_, "bounces");
  anyEnabled_ |= enable(light_, "light-scale");
  const bool reflectance = surface_->count() > 0;
  surface_->setEnabled(reflectance);
  for (auto* s : rho_) s->setEnabled(reflectance);
  anyEnabled_ |= reflectance;
  reset_->setEnabled(anyEnabled_);
  hint_->setText(anyEnabled_
                     ? tr("Changes apply after a short pause. A change of light or reflectance re-solves "
                          "without recomputing the form factors.")
                     : tr("This step has no parameters to change."));
  fillWidgets();
}

void ParameterPanel::fillWidgets() {
  const bool wasLoading = loading_;
  loading_ = true;
  auto setCombo = [](QComboBox* box, const std::string& value) {
    const int i = box->findText(QString::fromStdString(value));
    if (i >= 0) box->setCurrentIndex(i);
  };
  setCombo(method_, parameters_.method);
  setCombo(solver_, parameters_.solver);
  resolution_->setValue(parameters_.resolution.value_or(FormFactorOptions{}.hemicubeResolution));
  samples_->setValue(parameters_.samples.value_or(FormFactorOptions{}.samples));
  subdivide_->setValue(parameters_.subdivide.value_or(1));
  iterations_->setValue(parameters_.iterations.value_or(SolverOptions{}.maxIterations));
  bounces_->setValue(parameters_.bounces);
  light_->setValue(parameters_.lightScale);
  showSurfaceReflectance();
  loading_ = wasLoading;
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

void ParameterPanel::scheduleApply() {
  if (loading_) return;
  readWidgets();
  debounce_->start();
}

void ParameterPanel::readWidgets() {
  if (method_->isEnabled() && !method_->currentText().isEmpty())
    parameters_.method = method_->currentText().toStdString();
  if (solver_->isEnabled() && !solver_->currentText().isEmpty())
    parameters_.solver = solver_->currentText().toStdString();
  if (resolution_->isEnabled()) parameters_.resolution = resolution_->value();
  if (samples_->isEnabled()) parameters_.samples = samples_->value();
  if (subdivide_->isEnabled()) parameters_.subdivide = subdivide_->value(), parameters_.maxEdge.reset();
  if (iterations_->isEnabled()) parameters_.iterations = iterations_->value();
  if (bounces_->isEnabled()) parameters_.bounces = bounces_->value();
  if (light_->isEnabled()) parameters_.lightScale = light_->value();
  if (surface_->isEnabled() && surface_->count() > 0) {
    const std::string surface = surface_->currentText().toStdString();
    const Rgb rho(rho_[0]->value(), rho_[1]->value(), rho_[2]->value());
    // Only a value that differs from the scene's becomes an override (keeps the step's parameters as
    // written).
    if (parameters_.reflectance.count(surface) > 0 || !(rho - sceneReflectance(surface)).isZero(1e-9))
      parameters_.reflectance[surface] = rho;
  }
}

void ParameterPanel::applyNow() {
  debounce_->stop();
  emit parametersChanged(parameters_);
}

void ParameterPanel::setLightScale(double scale) {
  light_->setValue(scale);
  readWidgets();
}

void ParameterPanel::setReflectance(const QString& surface, double r, double g, double b) {
  surface_->setCurrentText(surface);
  loading_ = true;
  rho_[0]->setValue(r);
  rho_[1]->setValue(g);
  rho_[2]->setValue(b);
  loading_ = false;
  readWidgets();
}

void ParameterPanel::setSolver(const QString& name) {
  solver_->setCurrentText(name);
  readWidgets();
}

void ParameterPanel::setMethod(const QString& name) {
  method_->setCurrentText(name);
  readWidgets();
}

}  // namespace rt::app
