#include "ui/common/table_columns.h"

#include <QHeaderView>
#include <QTableWidget>

namespace multidir::ui {

void fitColumnsToWidth(QTableWidget* table, int elidedColumn) {
  for (int column = 0; column < table->columnCount(); ++column) {
    QTableWidgetItem* item = table->horizontalHeaderItem(column);
    if (item == nullptr) continue;
    QString text = item->text();
    // "Contact (mm²)" -> "Contact" over "(mm²)": a header is then as wide as its word, not word and unit.
    const int unit = text.lastIndexOf(QStringLiteral(" ("));
    if (unit > 0) text[unit] = QLatin1Char('\n');
    item->setText(text);
  }
  QHeaderView* header = table->horizontalHeader();
  header->setStretchLastSection(false);
  header->setSectionResizeMode(QHeaderView::ResizeToContents);
  header->setSectionResizeMode(elidedColumn, QHeaderView::Stretch);
  header->setMinimumSectionSize(24);
  table->setTextElideMode(Qt::ElideRight);
  table->setWordWrap(false);
}

void setTextTooltips(QTableWidget* table, int column) {
  for (int row = 0; row < table->rowCount(); ++row)
    if (QTableWidgetItem* item = table->item(row, column); item != nullptr && item->toolTip().isEmpty())
      item->setToolTip(item->text());
}

}  // namespace multidir::ui
