#pragma once
// The plan shown printed apart on an ordinary printer (docs/apart.md): the pipeline's result and the folder its
// files were written to. The studio document holds the one for the plan shown (StudioDocument::apartPrint);
// the Print apart view makes it and exports its files.
#include <QMetaType>
#include <QTemporaryDir>
#include <memory>

#include "multidir/apart/print_apart.h"
#include "multidir/core/search/decomposition.h"

namespace multidir::ui {

struct ApartPrint {
  std::shared_ptr<const core::Decomposition> plan;    // the plan it was made from
  std::shared_ptr<const apart::ApartResult> result;   // never null in the document
  std::shared_ptr<const QTemporaryDir> files;         // holds result->folder; removed with the last copy
};

}  // namespace multidir::ui

Q_DECLARE_METATYPE(multidir::ui::ApartPrint)
