#!/usr/bin/env python3
"""wav_svg.py WAV SVG - a picture of a recording's sound (docs/sound.md):
its mean spectrum (both channels, dB, 50 Hz..20 kHz, log frequency) and
its stereo balance over time ((R - L) / (R + L) of the power in 0.25 s
windows, -1 all left, +1 all right). Standard library only."""
import cmath
import math
import struct
import sys
import wave


def fft(a):
    n = len(a)
    if n == 1:
        return a
    even, odd = fft(a[0::2]), fft(a[1::2])
    t = [cmath.exp(-2j * math.pi * k / n) * odd[k] for k in range(n // 2)]
    return [even[k] + t[k] for k in range(n // 2)] + [even[k] - t[k] for k in range(n // 2)]


def main():
    w = wave.open(sys.argv[1])
    rate, n = w.getframerate(), w.getnframes()
    s = struct.unpack('<%dh' % (2 * n), w.readframes(n))
    left, right = s[0::2], s[1::2]
    N = 2048
    hann = [0.5 - 0.5 * math.cos(2 * math.pi * i / N) for i in range(N)]
    spec = [0.0] * (N // 2)
    starts = range(0, n - N, max(N, (n - N) // 40))
    for st in starts:
        for ch in (left, right):
            f = fft([ch[st + i] * hann[i] / 32768 for i in range(N)])
            for k in range(N // 2):
                spec[k] += abs(f[k]) ** 2
    cnt = 2 * len(starts)
    db = [10 * math.log10(v / cnt + 1e-12) for v in spec]
    win = rate // 4
    bal = []
    for st in range(0, n - win + 1, win):
        pl = sum(x * x for x in left[st:st + win])
        pr = sum(x * x for x in right[st:st + win])
        bal.append((pr - pl) / (pr + pl) if pr + pl > 0 else 0)
    W, H = 720, 220
    out = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" font-family="sans-serif" font-size="11">' % (W, 2 * H + 20),
           '<rect width="100%" height="100%" fill="white"/>']
    # spectrum
    lo, hi = math.log10(50), math.log10(20000)
    top = max(db[1:])
    pts = []
    for k in range(1, N // 2):
        fr = k * rate / N
        if fr < 50 or fr > 20000:
            continue
        x = 40 + (math.log10(fr) - lo) / (hi - lo) * (W - 60)
        y = 20 + (top - db[k]) / 80 * (H - 40)
        pts.append('%.1f,%.1f' % (x, min(y, H - 20)))
    out.append('<text x="40" y="14">mean spectrum (dB, 0 = peak; 80 dB shown)</text>')
    out.append('<polyline fill="none" stroke="#1565c0" points="%s"/>' % ' '.join(pts))
    for fr in (100, 1000, 10000):
        x = 40 + (math.log10(fr) - lo) / (hi - lo) * (W - 60)
        out.append('<line x1="%.1f" y1="20" x2="%.1f" y2="%d" stroke="#ccc"/>' % (x, x, H - 20))
        out.append('<text x="%.1f" y="%d">%s Hz</text>' % (x - 12, H - 6, fr))
    # balance
    y0 = H + 20
    out.append('<text x="40" y="%d">stereo balance over time (+1 right, -1 left), %d s</text>' % (y0 + 4, n // rate))
    mid = y0 + H / 2
    out.append('<line x1="40" y1="%.1f" x2="%d" y2="%.1f" stroke="#ccc"/>' % (mid, W - 20, mid))
    pts = ['%.1f,%.1f' % (40 + i / max(1, len(bal) - 1) * (W - 60), mid - b * (H / 2 - 20)) for i, b in enumerate(bal)]
    out.append('<polyline fill="none" stroke="#c62828" points="%s"/>' % ' '.join(pts))
    out.append('<text x="4" y="%.1f">R</text><text x="4" y="%.1f">L</text>' % (y0 + 24, y0 + H - 14))
    out.append('</svg>')
    open(sys.argv[2], 'w').write('\n'.join(out) + '\n')


main()
