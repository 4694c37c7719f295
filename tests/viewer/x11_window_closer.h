#pragma once
// Asks a window of another process to close, as a window manager's close button does: a
// WM_DELETE_WINDOW client message to the top-level window with the given title. libX11 is opened at
// run time (it is on every machine with an X server), so the tests need no link to it.
#include <X11/Xlib.h>
#include <dlfcn.h>

#include <string>

namespace glint::testing {

// True when a window titled `title` was found on the current DISPLAY and sent the message.
inline bool close_x11_window(const std::string& title) {
  void* x11 = ::dlopen("libX11.so.6", RTLD_NOW | RTLD_LOCAL);
  if (x11 == nullptr) return false;
  const auto symbol = [&](const char* name) { return ::dlsym(x11, name); };
  const auto open_display = reinterpret_cast<Display* (*)(const char*)>(symbol("XOpenDisplay"));
  const auto close_display = reinterpret_cast<int (*)(Display*)>(symbol("XCloseDisplay"));
  const auto query_tree =
      reinterpret_cast<Status (*)(Display*, Window, Window*, Window*, Window**, unsigned*)>(symbol("XQueryTree"));
  const auto fetch_name = reinterpret_cast<Status (*)(Display*, Window, char**)>(symbol("XFetchName"));
  const auto free = reinterpret_cast<int (*)(void*)>(symbol("XFree"));
  const auto intern_atom = reinterpret_cast<Atom (*)(Display*, const char*, Bool)>(symbol("XInternAtom"));
  const auto send_event = reinterpret_cast<Status (*)(Display*, Window, Bool, long, XEvent*)>(symbol("XSendEvent"));
  const auto flush = reinterpret_cast<int (*)(Display*)>(symbol("XFlush"));
  bool sent = false;
  if (Display* display = open_display(nullptr)) {
    Window root = DefaultRootWindow(display), parent = 0, *children = nullptr;
    unsigned count = 0;
    if (query_tree(display, root, &root, &parent, &children, &count) != 0) {
      for (unsigned i = 0; i < count && !sent; ++i) {
        char* name = nullptr;
        if (fetch_name(display, children[i], &name) != 0 && name != nullptr) {
          if (title == name) {
            XEvent event{};
            event.xclient.type = ClientMessage;
            event.xclient.window = children[i];
            event.xclient.message_type = intern_atom(display, "WM_PROTOCOLS", False);
            event.xclient.format = 32;
            event.xclient.data.l[0] = static_cast<long>(intern_atom(display, "WM_DELETE_WINDOW", False));
            event.xclient.data.l[1] = CurrentTime;
            sent = send_event(display, children[i], False, NoEventMask, &event) != 0;
            flush(display);
          }
          free(name);
        }
      }
      if (children != nullptr) free(children);
    }
    close_display(display);
  }
  ::dlclose(x11);
  return sent;
}

}  // namespace glint::testing
