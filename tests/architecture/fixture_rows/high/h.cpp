// uses only low/, though its row (rows_unused.cmake) allows mid/ and GL as well
#include "low/a.h"
