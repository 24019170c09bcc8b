// A fault injector for the publish test (tests/preprocess/asset_publish_test.cpp), preloaded
// into `gfield` with LD_PRELOAD. It counts the calls that change a folder (rename, link,
// symlink, unlink, rmdir, mkdir and their *at forms) and makes call number $GFIELD_FAULT_CALL
// (1-based) fail with EPERM ($GFIELD_FAULT=fail, as an immutable or busy target does) or kill
// the process with SIGKILL before it happens ($GFIELD_FAULT=kill). With $GFIELD_FAULT_COUNT set
// to a file name, it writes the number of such calls there at exit.
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static long calls = 0;

/// 0 to go on with the call, -1 (errno EPERM) to fail it; kills the process when told to.
static int fault_here(void) {
  const long n = __atomic_add_fetch(&calls, 1, __ATOMIC_SEQ_CST);
  const char* at = getenv("GFIELD_FAULT_CALL");
  if (at == NULL || atol(at) != n)
    return 0;
  const char* how = getenv("GFIELD_FAULT");
  if (how != NULL && strcmp(how, "kill") == 0)
    raise(SIGKILL);
  errno = EPERM;
  return -1;
}

__attribute__((destructor)) static void write_count(void) {
  const char* file = getenv("GFIELD_FAULT_COUNT");
  if (file == NULL)
    return;
  FILE* out = fopen(file, "w");
  if (out != NULL) {
    fprintf(out, "%ld\n", calls);
    fclose(out);
  }
}

#define NEXT(name) ((__typeof__(&name))dlsym(RTLD_NEXT, #name))

int rename(const char* from, const char* to) {
  return fault_here() ? -1 : NEXT(rename)(from, to);
}
int renameat(int fd1, const char* from, int fd2, const char* to) {
  return fault_here() ? -1 : NEXT(renameat)(fd1, from, fd2, to);
}
int renameat2(int fd1, const char* from, int fd2, const char* to, unsigned flags) {
  return fault_here() ? -1 : NEXT(renameat2)(fd1, from, fd2, to, flags);
}
int link(const char* from, const char* to) {
  return fault_here() ? -1 : NEXT(link)(from, to);
}
int linkat(int fd1, const char* from, int fd2, const char* to, int flags) {
  return fault_here() ? -1 : NEXT(linkat)(fd1, from, fd2, to, flags);
}
int symlink(const char* target, const char* path) {
  return fault_here() ? -1 : NEXT(symlink)(target, path);
}
int symlinkat(const char* target, int fd, const char* path) {
  return fault_here() ? -1 : NEXT(symlinkat)(target, fd, path);
}
int unlink(const char* path) {
  return fault_here() ? -1 : NEXT(unlink)(path);
}
int unlinkat(int fd, const char* path, int flags) {
  return fault_here() ? -1 : NEXT(unlinkat)(fd, path, flags);
}
int rmdir(const char* path) {
  return fault_here() ? -1 : NEXT(rmdir)(path);
}
int mkdir(const char* path, mode_t mode) {
  return fault_here() ? -1 : NEXT(mkdir)(path, mode);
}
int mkdirat(int fd, const char* path, mode_t mode) {
  return fault_here() ? -1 : NEXT(mkdirat)(fd, path, mode);
}
