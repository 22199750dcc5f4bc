/* A few checks for the C API's tests in C (tests/c/). */
#ifndef BREAKSHOT_TESTS_C_CHECK_H
#define BREAKSHOT_TESTS_C_CHECK_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "breakshot.h"

static int g_checks = 0;
static int g_failures = 0;

#define CHECK(cond)                                                         \
  do {                                                                      \
    ++g_checks;                                                             \
    if (!(cond)) {                                                          \
      ++g_failures;                                                         \
      fprintf(stderr, "%s:%d: CHECK failed: %s\n", __FILE__, __LINE__, #cond); \
    }                                                                       \
  } while (0)

/* A call that must succeed; on failure the status and message are shown. */
#define OK(call)                                                                  \
  do {                                                                            \
    BsStatus st_ = (call);                                                        \
    ++g_checks;                                                                   \
    if (st_ != BS_OK) {                                                           \
      ++g_failures;                                                               \
      fprintf(stderr, "%s:%d: %s gave %s\n", __FILE__, __LINE__, #call,           \
              bs_status_name(st_));                                               \
    }                                                                             \
  } while (0)

/* A call that must fail with `status` and leave a message on `handle`
 * (NULL: the thread's) that contains `part`. */
#define FAILS(call, status, handle, part)                                            \
  do {                                                                               \
    BsStatus st_ = (call);                                                           \
    const char* msg_ = bs_error_message(handle);                                     \
    ++g_checks;                                                                      \
    if (st_ != (status) || msg_ == NULL || msg_[0] == '\0' || strstr(msg_, part) == NULL) { \
      ++g_failures;                                                                  \
      fprintf(stderr, "%s:%d: %s gave %s \"%s\", expected %s with \"%s\"\n", __FILE__, \
              __LINE__, #call, bs_status_name(st_), msg_ ? msg_ : "(null)", #status, part); \
    }                                                                                \
  } while (0)

/* The contents of a file (NUL-terminated; its length in *len), or NULL. */
static inline char* read_file(const char* path, size_t* len) {
  FILE* f = fopen(path, "rb");
  char* text;
  long n;
  if (f == NULL) return NULL;
  if (fseek(f, 0, SEEK_END) != 0 || (n = ftell(f)) < 0 || fseek(f, 0, SEEK_SET) != 0) {
    fclose(f);
    return NULL;
  }
  text = (char*)malloc((size_t)n + 1);
  if (text == NULL || fread(text, 1, (size_t)n, f) != (size_t)n) {
    free(text);
    fclose(f);
    return NULL;
  }
  text[n] = '\0';
  fclose(f);
  if (len != NULL) *len = (size_t)n;
  return text;
}

static inline int check_summary(const char* name) {
  printf("%s: %d checks, %d failed\n", name, g_checks, g_failures);
  return g_failures == 0 ? 0 : 1;
}

#endif
