/* The floor for sherpa-bench-startup: a program linked to the same libc, doing the
   least a program can do that still writes to stdout. */
#include <stdio.h>

int main(void) {
    puts("hello");
    return 0;
}
