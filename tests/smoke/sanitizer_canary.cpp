// A deliberate heap overflow ("heap") or signed overflow ("ub") for the sanitized trees
// (make sanitize, make asan): their tests pass only when the sanitizer reports it, so that a
// tree that lost its -fsanitize flags cannot pass the sanitizer step silently.
#include <cstdio>
#include <cstring>
#include <limits>
#include <vector>

int main(int argc, char** argv) {
  const bool heap = argc > 1 && std::strcmp(argv[1], "heap") == 0;
  volatile int index = 4;  // volatile: not folded away by the optimiser
  if (heap) {
    std::vector<int> v(4, 1);
    std::printf("read %d\n", v.data()[index]);  // one past the end
  } else {
    volatile int big = std::numeric_limits<int>::max();
    std::printf("sum %d\n", big + index);  // signed overflow
  }
  return 0;
}
