/* studio_stack.c — lets civetweb start its threads inside fabvdb. Debian's
 * libcivetweb is built with USE_STACK_SIZE=102400 and asks for that stack on
 * every thread it starts, but glibc carves each thread's static TLS out of
 * the same stack, and the libraries fabvdb loads need about 104 KiB of it
 * (32 KiB of it a CGAL thread_local in libfabvdb), so pthread_create refuses
 * those threads (EINVAL) and `fabvdb studio` could not serve. This definition
 * of pthread_attr_setstacksize in the executable takes precedence over
 * glibc's for every library of the process (the dynamic linker looks in the
 * executable first; the build exports it from fabvdb, whose symbols are
 * otherwise hidden); it raises a size below STUDIO_MIN_STACK to it and passes
 * every size on to glibc's. Costs: 1 MiB of address space (not memory) per
 * such thread. */
#define _GNU_SOURCE /* RTLD_NEXT */
#include <dlfcn.h>
#include <errno.h>
#include <pthread.h>
#include <stddef.h>

#define STUDIO_MIN_STACK ((size_t)1 << 20)

__attribute__((visibility("default"))) int pthread_attr_setstacksize(pthread_attr_t* attr, size_t size) {
    int (*const glibc)(pthread_attr_t*, size_t) =
        (int (*)(pthread_attr_t*, size_t))dlsym(RTLD_NEXT, "pthread_attr_setstacksize");
    if (!glibc) return ENOSYS;
    return glibc(attr, size < STUDIO_MIN_STACK ? STUDIO_MIN_STACK : size);
}
