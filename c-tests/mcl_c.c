/* mcl_c.c: the MC3B library (include/mcl.h) called from C: the guide's status codes for
 * calls before mcl_initialize and for a port that does not exist (MC3B guide section 4). */
#include <stdlib.h>
#include "mcl.h"
#include "check.h"

/* The C runtime of Windows names POSIX's setenv _putenv_s (it also sets the process's
 * environment, which the library reads). */
#ifdef _WIN32
#define setenv(name, value, overwrite) _putenv_s(name, value)
#endif

int main(void)
{
    int version = -1, n = -1, status = -1;
    CHECK_EQ(mcl_get_library_version(&version), MCL_NO_ERROR);
    CHECK(version > 0);
    /* Section 4: every call but the version needs mcl_initialize first. */
    CHECK_EQ(mcl_set_motor_acceleration(0, 0, 1000), MCL_NOT_INITIALIZED_ERROR);
    CHECK_EQ(mcl_move_motor(0, 0, 0, 100), MCL_NOT_INITIALIZED_ERROR);
    CHECK_EQ(mcl_get_motor_status(0, 0, &status), MCL_NOT_INITIALIZED_ERROR);
    CHECK_EQ(mcl_deinitialize(), MCL_NOT_INITIALIZED_ERROR);
    /* COM1 mapped to a path that does not exist: SERIAL PORT ERROR. */
    setenv("MCL_COM1", "/nonexistent/ttyMC3B", 1);
    CHECK_EQ(mcl_initialize(1, &n), MCL_SERIAL_PORT_ERROR);
    CHECK_EQ(mcl_move_motor(0, 0, 0, 100), MCL_NOT_INITIALIZED_ERROR);
    return check_done("mcl_c");
}
