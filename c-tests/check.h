/* check.h: a tiny assertion helper shared by the C and C++ test programs.
 * CHECK(cond) and CHECK_EQ(a, b) print the failing line and count it;
 * check_done() prints a summary and returns the exit code. */
#ifndef MCCL_TEST_CHECK_H
#define MCCL_TEST_CHECK_H
#include <stdio.h>
#include <math.h>

static int check_failures = 0;
static int check_passes = 0;

#define CHECK(cond)                                                          \
  do {                                                                       \
    if (cond) {                                                              \
      check_passes++;                                                        \
    } else {                                                                 \
      check_failures++;                                                      \
      fprintf(stderr, "%s:%d: CHECK failed: %s\n", __FILE__, __LINE__, #cond); \
    }                                                                        \
  } while (0)

#define CHECK_EQ(a, b)                                                       \
  do {                                                                       \
    long long check_a_ = (long long)(a), check_b_ = (long long)(b);          \
    if (check_a_ == check_b_) {                                              \
      check_passes++;                                                        \
    } else {                                                                 \
      check_failures++;                                                      \
      fprintf(stderr, "%s:%d: CHECK_EQ failed: %s == %lld, expected %s == %lld\n", \
              __FILE__, __LINE__, #a, check_a_, #b, check_b_);               \
    }                                                                        \
  } while (0)

#define CHECK_NEAR(a, b, tol)                                                \
  do {                                                                       \
    double check_a_ = (double)(a), check_b_ = (double)(b);                   \
    if (fabs(check_a_ - check_b_) <= (tol)) {                                \
      check_passes++;                                                        \
    } else {                                                                 \
      check_failures++;                                                      \
      fprintf(stderr, "%s:%d: CHECK_NEAR failed: %s == %.12g, expected %.12g (tol %g)\n", \
              __FILE__, __LINE__, #a, check_a_, check_b_, (double)(tol));    \
    }                                                                        \
  } while (0)

static int check_done(const char *name) {
  printf("%s: %d passed, %d failed\n", name, check_passes, check_failures);
  return check_failures == 0 ? 0 : 1;
}
#endif
