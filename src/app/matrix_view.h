// The form-factor matrix as a table: row i is what element i sees. Cells are shaded by value (log scale) so
// the structure shows at a glance. Selecting a row or a cell names elements; the window highlights them in
// the 3D views, and picking an element in a view selects its row here (linked selection).
#pragma once

#include <QAbstractTableModel>
#include <QTableView>
#include <memory>

#include "core/formfactor/formfactor_matrix.h"

namespace rt::app {

class MatrixModel : public QAbstractTableModel {
  Q_OBJECT
 public:
  using QAbstractTableModel::QAbstractTableModel;
  void setMatrix(std::shared_ptr<const FormFactorMatrix> F);
  const FormFactorMatrix* matrix() const { return F_.get(); }
  int rowCount(const QModelIndex& parent = QModelIndex()) const override;
  int columnCount(const QModelIndex& parent = QModelIndex()) const override;
  QVariant data(const QModelIndex& index, int role) const override;
  QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

 private:
  std::shared_ptr<const FormFactorMatrix> F_;
  double logMin_ = -6, logMax_ = 0;
};

class MatrixView : public QTableView {
  Q_OBJECT
 public:
  explicit MatrixView(QWidget* parent = nullptr);
  void setMatrix(std::shared_ptr<const FormFactorMatrix> F);
  MatrixModel* matrixModel() const { return model_; }
  // Selects and shows row `element` (from a pick in a view) without emitting elementsSelected.
  void selectElementRow(int element);

 signals:
  // A clicked cell (i, j): both elements; a clicked row header: that element.
  void elementsSelected(int row, int column);

 private:
  MatrixModel* model_ = nullptr;
  bool selecting_ = false;
};

}  // namespace rt::app
