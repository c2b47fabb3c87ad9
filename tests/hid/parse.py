import re
_P = {
 "({idx:x})\t{page_name}": (r"^\(([0-9a-fA-F]+)\)\t(.*)$", lambda m: {"idx": int(m.group(1),16), "page_name": m.group(2)}),
 "{:x}-{:x}\t{name}": (r"^([0-9a-fA-F]+)-([0-9a-fA-F]+)\t(.*)$", lambda m: {"name": m.group(3)}),
 "{usage}\t{name}": (r"^([^\t]+)\t(.*)$", lambda m: {"usage": m.group(1), "name": m.group(2)}),
}
def parse(fmt, line):
    rx, f = _P[fmt]
    m = re.match(rx, line)
    return f(m) if m else None
