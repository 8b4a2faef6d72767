/* Fixed LuaJIT trace seeds, for comparing two versions of the code by the same traces.
 * LuaJIT 2.1 seeds the random penalties of its trace recorder with syscall(SYS_getrandom), so
 * the traces (and the time and the machine instructions of a call) differ from run to run.
 * Preloaded, this answers that one system call with bytes from TRACE_SEED (a number, 1 if
 * unset) and passes every other call on. With address randomization off too, a -jdump is then
 * the same from run to run:
 *   gcc -shared -fPIC -O2 -o /tmp/fixseed.so bench/fixseed.c -ldl
 *   TRACE_SEED=3 LD_PRELOAD=/tmp/fixseed.so setarch -R luajit bench/compound.lua ratio pushFloor pushPairs 100000
 */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stdarg.h>
#include <stdlib.h>
#include <sys/syscall.h>

long syscall(long number, ...) {
  va_list ap;
  long arg[6];
  va_start(ap, number);
  for (int i = 0; i < 6; i++) arg[i] = va_arg(ap, long);
  va_end(ap);
  if (number == SYS_getrandom) {
    const char *text = getenv("TRACE_SEED");
    unsigned long long state = text ? strtoull(text, 0, 10) : 1;
    unsigned char *out = (unsigned char *)arg[0];
    for (long i = 0; i < arg[1]; i++) {   /* a 64-bit linear congruential generator's top bytes */
      state = state * 6364136223846793005ULL + 1442695040888963407ULL;
      out[i] = (unsigned char)(state >> 56);
    }
    return arg[1];
  }
  static long (*next)(long, ...);
  if (!next) next = (long (*)(long, ...))dlsym(RTLD_NEXT, "syscall");
  return next(number, arg[0], arg[1], arg[2], arg[3], arg[4], arg[5]);
}
