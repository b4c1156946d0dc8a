#include "app/progress_strip.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <algorithm>

#include "core/time_left.h"

namespace rt::app {

ProgressStrip::ProgressStrip(QWidget* parent) : QWidget(parent) {
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  label_ = new QLabel(this);
  label_->setObjectName("progressLabel");
  bar_ = new QProgressBar(this);
  bar_->setObjectName("progressBar");
  bar_->setRange(0, 1000);
  bar_->setMinimumWidth(220);
  bar_->setMaximumWidth(360);
  cancel_ = new QPushButton(tr("Cancel"), this);
  cancel_->setObjectName("cancelButton");
  cancel_->setToolTip(tr("Stop this computation: the previous result stays on screen"));
  // Never a default button: Enter or Space meant for the step text must not cancel by accident.
  cancel_->setAutoDefault(false);
  cancel_->setFocusPolicy(Qt::NoFocus);
  layout->addWidget(label_);
  layout->addWidget(bar_);
  layout->addWidget(cancel_);
  connect(cancel_, &QPushButton::clicked, this, [this] {
    label_->setText(tr("Cancelling %1...").arg(what_.toLower()));
    cancel_->setEnabled(false);  // one click is enough; the job stops at its next progress check
    emit cancelRequested();
  });
  showTimer_.setSingleShot(true);
  showTimer_.setInterval(kShowDelayMs);
  connect(&showTimer_, &QTimer::timeout, this, [this] {
    if (!active_) return;
    show();
    emit appeared();
  });
  hide();
}

void ProgressStrip::begin(const QString& what) {
  what_ = what;
  active_ = true;
  label_->setText(what);
  bar_->setValue(0);
  bar_->setFormat("%p%");
  cancel_->setEnabled(true);
  stage_.clear();
  stageTimer_.start();
  showTimer_.start();
}

void ProgressStrip::setProgress(double fraction, const QString& stage) {
  if (!active_) return;
  bar_->setValue(static_cast<int>(std::clamp(fraction, 0.0, 1.0) * 1000));
  bar_->setFormat(stage.isEmpty() ? QString("%p%") : stage + "  %p%");
  // Each stage starts again from 0 %: the estimate of the time left is per stage.
  if (stage != stage_) {
    stage_ = stage;
    stageTimer_.restart();
  }
  if (!cancel_->isEnabled()) return;  // "Cancelling..." stays
  const std::string left = describeTimeLeft(static_cast<double>(stageTimer_.elapsed()) / 1000.0, fraction);
  label_->setText(left.empty() ? what_
                               : what_ + QString::fromUtf8(" \u2014 ") + QString::fromStdString(left));
}

void ProgressStrip::end() {
  active_ = false;
  showTimer_.stop();
  hide();
}

int ProgressStrip::value() const {
  return bar_->value();
}

QString ProgressStrip::text() const {
  return bar_->text();
}

QString ProgressStrip::label() const {
  return label_->text();
}

}  // namespace rt::app
