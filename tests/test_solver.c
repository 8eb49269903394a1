#include "test.h"
void suite_solver(void) {}
