/* x11_shot.c - test helper: what a box of a window shows, as a digest, so
 * a test can tell whether a key changed that part of the picture (Xvfb has
 * no screenshot tool of its own here).
 *
 * Usage: x11_shot NAME X0 Y0 X1 Y1. The box is in per cent of the window
 * named NAME (a top-level window on $DISPLAY), X0..X1 and Y0..Y1, from the
 * top left. Prints one line: a 64-bit FNV-1a digest of the box's pixels
 * (red, green, blue of each, rows top to bottom) in hex. Exit status: 0
 * printed, 1 no such window (or no display, or it could not be read), 2
 * usage. */
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static Window find(Display *d, const char *name)
{
    Window root = DefaultRootWindow(d), parent, *kids = NULL, found = 0;
    unsigned n = 0;
    XQueryTree(d, root, &root, &parent, &kids, &n);
    for (unsigned i = 0; i < n && !found; i++) {
        char *s = NULL;
        if (XFetchName(d, kids[i], &s) && s && !strcmp(s, name))
            found = kids[i];
        if (s)
            XFree(s);
    }
    if (kids)
        XFree(kids);
    return found;
}

static uint64_t digest(XImage *im)
{
    uint64_t h = 1469598103934665603u;
    for (int y = 0; y < im->height; y++)
        for (int x = 0; x < im->width; x++) {
            unsigned long p = XGetPixel(im, x, y);
            unsigned char rgb[3] = {(unsigned char)((p & im->red_mask) >> 16),
                                    (unsigned char)((p & im->green_mask) >> 8),
                                    (unsigned char)(p & im->blue_mask)};
            for (int k = 0; k < 3; k++)
                h = (h ^ rgb[k]) * 1099511628211u;
        }
    return h;
}

int main(int argc, char **argv)
{
    int box[4];
    if (argc != 6) {
        fprintf(stderr, "usage: x11_shot NAME X0 Y0 X1 Y1 (per cent)\n");
        return 2;
    }
    for (int i = 0; i < 4; i++) {
        box[i] = atoi(argv[2 + i]);
        if (box[i] < 0 || box[i] > 100) {
            fprintf(stderr, "x11_shot: %s is not a per cent\n", argv[2 + i]);
            return 2;
        }
    }
    Display *d = XOpenDisplay(NULL);
    if (!d)
        return 1;
    Window w = find(d, argv[1]);
    XWindowAttributes a;
    if (!w || !XGetWindowAttributes(d, w, &a)) {
        XCloseDisplay(d);
        return 1;
    }
    int x0 = a.width * box[0] / 100, y0 = a.height * box[1] / 100;
    int x1 = a.width * box[2] / 100, y1 = a.height * box[3] / 100;
    XImage *im = x1 > x0 && y1 > y0
                     ? XGetImage(d, w, x0, y0, (unsigned)(x1 - x0), (unsigned)(y1 - y0),
                                 AllPlanes, ZPixmap)
                     : NULL;
    if (!im) {
        XCloseDisplay(d);
        return 1;
    }
    printf("%016llx\n", (unsigned long long)digest(im));
    XDestroyImage(im);
    XCloseDisplay(d);
    return 0;
}
