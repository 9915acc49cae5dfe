#pragma once
// JSON text checked with the messages plan files give, for readers of MultiDir's other JSON documents (the
// command line's print-job.json): a value no double holds (1e999) or a token JSON does not have (NaN,
// Infinity) is named by its field, not only by a byte offset.
#include <string>

#include "multidir/core/common/result.h"

namespace multidir::core {

// Done when `text` is one JSON document whose numbers are all finite doubles. Errors: MalformedFile naming
// `name`, the field where parsing stopped ("steps[0].angles.rotaryDegrees") and its token.
Status checkJsonText(const std::string& text, const std::string& name);

}  // namespace multidir::core
