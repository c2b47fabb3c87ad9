/* x11_close.c - test helper: press a window's close button as a window
 * manager would, by sending WM_DELETE_WINDOW to the top-level window named
 * NAME on $DISPLAY (Xvfb has no window manager to do it).
 *
 * Usage: x11_close NAME. Exit status: 0 sent, 1 no such window (or no
 * display), 2 usage. */
#include <X11/Xatom.h>
#include <X11/Xlib.h>
#include <stdio.h>
#include <string.h>

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: x11_close NAME\n");
        return 2;
    }
    Display *d = XOpenDisplay(NULL);
    if (!d)
        return 1;
    Window root = DefaultRootWindow(d), parent, *kids = NULL, found = 0;
    unsigned n = 0;
    XQueryTree(d, root, &root, &parent, &kids, &n);
    for (unsigned i = 0; i < n && !found; i++) {
        char *name = NULL;
        if (XFetchName(d, kids[i], &name) && name && !strcmp(name, argv[1]))
            found = kids[i];
        if (name)
            XFree(name);
    }
    if (kids)
        XFree(kids);
    if (!found) {
        XCloseDisplay(d);
        return 1;
    }
    XEvent ev;
    memset(&ev, 0, sizeof ev);
    ev.xclient.type = ClientMessage;
    ev.xclient.window = found;
    ev.xclient.message_type = XInternAtom(d, "WM_PROTOCOLS", False);
    ev.xclient.format = 32;
    ev.xclient.data.l[0] = (long)XInternAtom(d, "WM_DELETE_WINDOW", False);
    ev.xclient.data.l[1] = CurrentTime;
    XSendEvent(d, found, False, NoEventMask, &ev);
    XFlush(d);
    XCloseDisplay(d);
    return 0;
}
