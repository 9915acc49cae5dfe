#pragma once
// Tables in a dock fit its width: every header's unit on a line of its own ("Contact\n(mm²)"), numbers' columns
// as wide as their contents, and one column of text (`elidedColumn`) taking what is left, elided where it must
// be (its full text is the cell's tooltip), so the table does not scroll sideways.
class QTableWidget;

namespace multidir::ui {

// Call after the header labels are set.
void fitColumnsToWidth(QTableWidget* table, int elidedColumn);
// Each cell of `column` without a tooltip of its own gets its text as its tooltip (call after filling the table).
void setTextTooltips(QTableWidget* table, int column);

}  // namespace multidir::ui
