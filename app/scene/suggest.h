// The did-you-mean helper lives in core/suggest.h (preprocess/ and io/ use
// it too, below scene/); this name stays for the scene files that include it.
#pragma once
#include "core/suggest.h"
