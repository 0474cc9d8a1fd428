/* orthoslip.h is idempotent: including it twice compiles, as C11 and as C++17. */
#include "orthoslip.h"
#include "orthoslip.h"

orthoslip_status header_twice_ok(void);
orthoslip_status header_twice_ok(void)
{
    return ORTHOSLIP_OK;
}
