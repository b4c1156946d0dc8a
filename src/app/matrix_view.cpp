#include "app/matrix_view.h"

#include <QColor>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <cmath>

namespace rt::app {

void MatrixModel::setMatrix(std::shared_ptr<const FormFactorMatrix> F) {
  beginResetModel();
  F_ = std::move(F);
  logMin_ = -6;
  logMax_ = 0;
  if (F_ && F_->size() > 0) {
    const double largest = F_->maxCoeff();
    if (largest > 0) logMax_ = std::log10(largest), logMin_ = logMax_ - 5;
  }
  endResetModel();
}

int MatrixModel::rowCount(const QModelIndex& parent) const {
  return parent.isValid() || !F_ ? 0 : static_cast<int>(F_->rows());
}
int MatrixModel::columnCount(const QModelIndex& parent) const {
  return parent.isValid() || !F_ ? 0 : static_cast<int>(F_->cols());
}

QVariant MatrixModel::data(const QModelIndex& index, int role) const {
  if (!F_ || !index.isValid()) return {};
  const double value = (*F_)(index.row(), index.column());
  switch (role) {
    case Qt::DisplayRole:
      return value == 0 ? QString("0") : QString::number(value, 'g', 4);
    case Qt::ToolTipRole:
      return QString("F[%1][%2] = %3").arg(index.row()).arg(index.column()).arg(value, 0, 'g', 17);
    case Qt::BackgroundRole: {
      if (value <= 0) return QColor(255, 255, 255);
      // Log shading: a factor of ten per step of the five decades below the largest entry.
      const double t = std::clamp((std::log10(value) - logMin_) / (logMax_ - logMin_), 0.0, 1.0);
      return QColor::fromRgbF(1.0 - 0.75 * t, 1.0 - 0.45 * t, 1.0 - 0.1 * t);
    }
    case Qt::TextAlignmentRole:
      return int(Qt::AlignRight | Qt::AlignVCenter);
    default:
      return {};
  }
}

QVariant MatrixModel::headerData(int section, Qt::Orientation, int role) const {
  if (role == Qt::DisplayRole) return QString::number(section);
  return {};
}

MatrixView::MatrixView(QWidget* parent) : QTableView(parent) {
  model_ = new MatrixModel(this);
  setModel(model_);
  setSelectionMode(QAbstractItemView::SingleSelection);
  setSelectionBehavior(QAbstractItemView::SelectItems);
  horizontalHeader()->setDefaultSectionSize(64);
  verticalHeader()->setDefaultSectionSize(22);
  connect(this, &QTableView::clicked, this, [this](const QModelIndex& index) {
    if (index.isValid()) emit elementsSelected(index.row(), index.column());
  });
  connect(verticalHeader(), &QHeaderView::sectionClicked, this,
          [this](int row) { emit elementsSelected(row, -1); });
}

void MatrixView::setMatrix(std::shared_ptr<const FormFactorMatrix> F) {
  model_->setMatrix(std::move(F));
}

void MatrixView::selectElementRow(int element) {
  if (element < 0 || element >= model_->rowCount()) return;
  // Programmatic selection of the whole row (the click behaviour selects single cells).
  const QItemSelection row(model_->index(element, 0), model_->index(element, model_->columnCount() - 1));
  selectionModel()->select(row, QItemSelectionModel::ClearAndSelect);
  scrollTo(model_->index(element, 0), QAbstractItemView::PositionAtCenter);
}

}  // namespace rt::app
