#pragma once
// Tests use the production RAII scratch folder (core/temporary_folder.h).
#include "core/temporary_folder.h"

namespace maxillo::testing {
using maxillo::TemporaryFolder;
}
