// WAVELIT_CHECK: broken invariants (programming errors, never bad input) print file:line and abort.
#pragma once

#include <cstdio>
#include <cstdlib>

#define WAVELIT_CHECK(cond)                                                                        \
    do {                                                                                           \
        if (!(cond)) {                                                                             \
            std::fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #cond);          \
            std::abort();                                                                          \
        }                                                                                          \
    } while (0)

#define WAVELIT_CHECK_MSG(cond, msg)                                                               \
    do {                                                                                           \
        if (!(cond)) {                                                                             \
            std::fprintf(stderr, "%s:%d: check failed: %s (%s)\n", __FILE__, __LINE__, #cond,      \
                         msg);                                                                     \
            std::abort();                                                                          \
        }                                                                                          \
    } while (0)
