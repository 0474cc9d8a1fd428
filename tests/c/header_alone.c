/* orthoslip.h compiles on its own (no prior includes), as C11 and as C++17. */
#include "orthoslip.h"
