// Preloaded into pvbatch by `wirepack render` (app/render.cpp) when it runs under a virtual X
// server: XOpenDisplay with retries. In the containers this project runs in, the X server
// closes about one new connection in three before its setup reply (measured: 69 of 200 with
// Xvfb idle), and VTK's render window aborts the process on the first failed XOpenDisplay.
// Up to kTries attempts, kPauseNs apart (at most about 2 s when there is no server at all).
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stddef.h>
#include <time.h>

typedef struct _XDisplay Display;  // opaque: no X11 headers needed

enum { kTries = 40 };
static const long kPauseNs = 50L * 1000 * 1000;  // 50 ms [ns]

Display* XOpenDisplay(const char* name) {
  static Display* (*real)(const char*) = NULL;
  if (!real) *(void**)(&real) = dlsym(RTLD_NEXT, "XOpenDisplay");
  if (!real) return NULL;
  for (int i = 0; i < kTries; ++i) {
    Display* d = real(name);
    if (d) return d;
    const struct timespec pause = {0, kPauseNs};
    nanosleep(&pause, NULL);
  }
  return NULL;
}
