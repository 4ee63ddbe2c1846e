/* crash_on_pattern.c — a faulty libFuzzer target for tests/fuzz/raw_minimize.sh:
 * a heap-buffer-overflow (under AddressSanitizer) whenever the input holds
 * the bytes "BUG!" anywhere, however much else surrounds them. Everything
 * else is accepted. Built by the test itself with clang -fsanitize=fuzzer,address. */
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const unsigned char* data, size_t size) {
  for (size_t i = 0; i + 4 <= size; ++i)
    if (memcmp(data + i, "BUG!", 4) == 0) {
      volatile char* p = malloc(4);
      p[4] = 1; /* one past the end */
      free((void*)p);
    }
  return 0;
}
