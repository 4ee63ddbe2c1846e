#!/usr/bin/env python3
"""A clean-room Verse geometry node speaking the vgc exec protocol (version 1).

Written from the documentation alone (docs/commands.md, docs/adapters.md,
docs/clauses.md, docs/certify.md, the spec README and 000 section 2.6), as a
test of that documentation: no code of the suite was read.

Implements: commands.md section 1 (lexical rules and error columns), 2 (verbs
and fields), 3 (values in text: integers, layer types, real formats, reals
bit for bit, quoted names), 4 (node semantics), 5 (reasons), 6 (snapshot and
derived documents); adapters.md section 1 (the exec protocol).

Reals are stored as their 64-bit IEEE-754 bit patterns (Python ints), never
as computed floats, so NaN payloads and -0 survive untouched; struct converts
between bits and floats where arithmetic is needed (bone poses).

Standard library only. Usage: python3 vgc_node.py   (requests on stdin).
Fault injection for the suite's self-test: VGC_PY_FAULT=<name> (see FAULTS).
"""

import math
import os
import re
import struct
import sys
from fractions import Fraction

# --- seeded faults (a test proves the suite catches them) -------------------

FAULTS = {
    "accept-duplicate-corners",  # skip the pairwise-distinct corner check (POLY-DISTINCT-1)
}
FAULT = os.environ.get("VGC_PY_FAULT", "")
if FAULT and FAULT not in FAULTS:
    sys.stderr.write("vgc_node.py: unknown VGC_PY_FAULT %r\n" % FAULT)
    sys.exit(2)

# --- constants ---------------------------------------------------------------

U8_MAX, U16_MAX, U32_MAX = 0xFF, 0xFFFF, 0xFFFFFFFF
F64_SIGN = 1 << 63
F64_EXP = 0x7FF << 52
F64_DEFAULT_NAN = 0x7FF8000000000000
F32_DEFAULT_NAN = 0x7FC00000
FLT_MAX_BITS = 0x7F7FFFFF
DBL_MAX_BITS = 0x7FEFFFFFFFFFFFFF
MAX_CELLS_PER_STACK = 1 << 22  # commands.md 4.9, the reference's default

LAYER_TYPES = {  # commands.md 3.2
    "VERTEX_XYZ": 0, "VERTEX_UINT32": 1, "VERTEX_REAL": 2,
    "POLYGON_CORNER_UINT32": 128, "POLYGON_CORNER_REAL": 129,
    "POLYGON_FACE_UINT8": 130, "POLYGON_FACE_UINT32": 131, "POLYGON_FACE_REAL": 132,
}
LAYER_TYPE_NAMES = {v: k for k, v in LAYER_TYPES.items()}
VERTEX_XYZ, VERTEX_UINT32, VERTEX_REAL = 0, 1, 2
POLY_CORNER_UINT32, POLY_CORNER_REAL, POLY_FACE_UINT8, POLY_FACE_UINT32, POLY_FACE_REAL = 128, 129, 130, 131, 132
REAL_FORMATS = {"REAL32": 0, "REAL64": 1}
REAL_FORMAT_NAMES = {0: "REAL32", 1: "REAL64"}

# --- commands: the one field schema (commands.md section 2) -----------------

def _arr(name, n, typ):
    return [("%s[%d]" % (name, i), typ) for i in range(n)]

COMMANDS = {
    "layer_create": [("layer_id", "u16"), ("name", "name"), ("type", "type"), ("def_uint", "u32"), ("def_real", "f64")],
    "layer_destroy": [("layer_id", "u16")],
    "layer_subscribe": [("layer_id", "u16"), ("real_format", "format")],
    "layer_unsubscribe": [("layer_id", "u16")],
    "vertex_set_xyz_real32": [("layer_id", "u16"), ("vertex_id", "u32"), ("x", "f32"), ("y", "f32"), ("z", "f32")],
    "vertex_set_xyz_real64": [("layer_id", "u16"), ("vertex_id", "u32"), ("x", "f64"), ("y", "f64"), ("z", "f64")],
    "vertex_delete": [("vertex_id", "u32")],
    "vertex_set_uint32": [("layer_id", "u16"), ("vertex_id", "u32"), ("value", "u32")],
    "vertex_set_real64": [("layer_id", "u16"), ("vertex_id", "u32"), ("value", "f64")],
    "vertex_set_real32": [("layer_id", "u16"), ("vertex_id", "u32"), ("value", "f32")],
    "polygon_set_corner_uint32": [("layer_id", "u16"), ("polygon_id", "u32")] + _arr("v", 4, "u32"),
    "polygon_set_corner_real64": [("layer_id", "u16"), ("polygon_id", "u32")] + _arr("v", 4, "f64"),
    "polygon_set_corner_real32": [("layer_id", "u16"), ("polygon_id", "u32")] + _arr("v", 4, "f32"),
    "polygon_delete": [("polygon_id", "u32")],
    "polygon_set_face_uint8": [("layer_id", "u16"), ("polygon_id", "u32"), ("value", "u8")],
    "polygon_set_face_uint32": [("layer_id", "u16"), ("polygon_id", "u32"), ("value", "u32")],
    "polygon_set_face_real64": [("layer_id", "u16"), ("polygon_id", "u32"), ("value", "f64")],
    "polygon_set_face_real32": [("layer_id", "u16"), ("polygon_id", "u32"), ("value", "f32")],
    "crease_set_vertex": [("layer", "name"), ("def_crease", "u32")],
    "crease_set_edge": [("layer", "name"), ("def_crease", "u32")],
    "bone_create": [("bone_id", "u16"), ("weight", "name"), ("reference", "name"), ("parent", "u16")]
    + _arr("pos", 3, "f64") + [("pos_label", "name")] + _arr("rot", 4, "f64") + [("rot_label", "name")],
    "bone_destroy": [("bone_id", "u16")],
}

TYPE_TEXT = {
    "u8": "uint8", "u16": "uint16", "u32": "uint32", "f32": "real32", "f64": "real64",
    "name": "quoted name",
    "type": "layer type (VERTEX_XYZ ... POLYGON_FACE_REAL or 0..255)",
    "format": "real format (REAL32, REAL64 or 0..255)",
}

# --- real numbers: bits <-> text (commands.md 3.4) ---------------------------

class Fmt:
    """An IEEE-754 binary format: f32 or f64."""

    def __init__(self, mant_bits, exp_bits, struct_code):
        self.mant_bits = mant_bits
        self.exp_bits = exp_bits
        self.width = 1 + exp_bits + mant_bits
        self.bias = (1 << (exp_bits - 1)) - 1
        self.exp_mask = ((1 << exp_bits) - 1) << mant_bits
        self.mant_mask = (1 << mant_bits) - 1
        self.sign = 1 << (self.width - 1)
        self.default_nan = self.exp_mask | (1 << (mant_bits - 1))
        self.code = struct_code
        self.hexdigits = self.width // 4

    def is_nan(self, b):
        return (b & self.exp_mask) == self.exp_mask and (b & self.mant_mask) != 0

    def is_finite(self, b):
        return (b & self.exp_mask) != self.exp_mask

    def to_fraction(self, b):
        """Exact value of a finite bit pattern (sign ignored)."""
        e = (b & self.exp_mask) >> self.mant_bits
        m = b & self.mant_mask
        if e == 0:
            return Fraction(m) * Fraction(2) ** (1 - self.bias - self.mant_bits)
        return Fraction(m | (1 << self.mant_bits)) * Fraction(2) ** (e - self.bias - self.mant_bits)

    def round_fraction(self, fr):
        """Bits of the positive (or zero) exact value fr rounded to nearest even;
        None when it overflows to infinity."""
        if fr == 0:
            return 0
        p = self.mant_bits
        emin = 1 - self.bias
        e = fr.numerator.bit_length() - fr.denominator.bit_length()
        if Fraction(2) ** e > fr:
            e -= 1
        if e < emin:
            e = emin
        q = fr / Fraction(2) ** (e - p)
        m = round(q)  # Fraction.__round__ rounds half to even
        if m == 1 << (p + 1):
            m >>= 1
            e += 1
        if e > self.bias:
            return None
        if m < (1 << p):  # subnormal (only possible at emin)
            return m
        return ((e + self.bias) << p) | (m - (1 << p))


F32 = Fmt(23, 8, "<f")
F64 = Fmt(52, 11, "<d")


def bits_to_float(b):
    return struct.unpack("<d", struct.pack("<Q", b))[0]


def float_to_bits(x):
    return struct.unpack("<Q", struct.pack("<d", x))[0]


def widen_f32(b):
    """f32 bits -> f64 bits, as the C conversion (double)f does on IEEE hardware
    (a signalling NaN comes out quiet, the payload shifted into the top bits)."""
    sign = (b >> 31) << 63
    e = (b >> 23) & 0xFF
    m = b & 0x7FFFFF
    if e == 0xFF:
        if m == 0:
            return sign | F64_EXP
        return sign | F64_EXP | (m << 29) | (1 << 51)
    x = struct.unpack("<f", struct.pack("<I", b))[0]  # exact for non-NaN
    return float_to_bits(x)


def _shortest_digits_exact(fmt, b):
    """Shortest round-trip decimal of finite non-zero positive bits b in fmt:
    (digits string without leading/trailing zeros, exponent x so that
    value = d.ddd * 10**x). Closest candidate among the shortest."""
    v = fmt.to_fraction(b)
    # rounding interval: the midpoints to both neighbours, closed when the
    # mantissa is even (round-half-even reads a midpoint back as b)
    prev = fmt.to_fraction(b - 1)
    nxt = fmt.to_fraction(b + 1) if fmt.is_finite(b + 1) else v + (v - prev)
    lo, hi = (prev + v) / 2, (v + nxt) / 2
    closed = (b & 1) == 0

    def inside(c):
        return (lo <= c <= hi) if closed else (lo < c < hi)

    # decimal exponent of v: 10**x <= v < 10**(x+1)
    x = math.floor(math.log10(float(v)))
    while Fraction(10) ** x > v:
        x -= 1
    while Fraction(10) ** (x + 1) <= v:
        x += 1
    for n in range(1, 40):
        k = x - n + 1
        scale = Fraction(10) ** k
        q = v / scale
        fl = q.numerator // q.denominator
        cands = [fl, fl + 1]
        cands.sort(key=lambda c: (abs(Fraction(c) - q), c % 2))
        for c in cands:
            if c > 0 and inside(Fraction(c) * scale):
                digits = str(c)
                exp = k + len(digits) - 1
                return digits.rstrip("0"), exp
    raise AssertionError("no shortest representation")


def _shortest_digits_f64(x):
    r = repr(abs(x))
    if "e" in r:
        mant, e = r.split("e")
        e = int(e)
    else:
        mant, e = r, 0
    if "." in mant:
        ip, fp = mant.split(".")
    else:
        ip, fp = mant, ""
    if fp == "0":
        fp = ""
    digits = ip + fp
    # value = 0.digits... : position of the point after len(ip) digits
    stripped = digits.lstrip("0")
    lead = len(digits) - len(stripped)
    exp = e + len(ip) - 1 - lead
    return stripped.rstrip("0"), exp


def format_real(fmt, b):
    """commands.md 3.4 'Printed'."""
    sign = "-" if b & fmt.sign else ""
    mag = b & ~fmt.sign
    if fmt.is_nan(b):
        if b == fmt.default_nan:
            return "nan"
        return "nan(0x%0*X)" % (fmt.hexdigits, b)
    if mag == fmt.exp_mask:
        return sign + "inf"
    if mag == 0:
        return sign + "0"
    if fmt is F64:
        digits, x = _shortest_digits_f64(bits_to_float(mag))
    else:
        digits, x = _shortest_digits_exact(fmt, mag)
    n = len(digits)
    # scientific
    sci = digits[0] + ("." + digits[1:] if n > 1 else "") + "e" + ("-" if x < 0 else "+") + "%02d" % abs(x)
    # plain; an integer too long for its digits prints its exact value (%f-style)
    if x >= n - 1:
        plain = str(int(fmt.to_fraction(mag)))
    elif x >= 0:
        plain = digits[: x + 1] + "." + digits[x + 1:]
    else:
        plain = "0." + "0" * (-x - 1) + digits
    return sign + (plain if len(plain) <= len(sci) else sci)


_DEC_RE = re.compile(rb"(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?\Z")
_HEX_RE = re.compile(rb"0[xX](?:([0-9a-fA-F]+)\.?([0-9a-fA-F]*)|\.([0-9a-fA-F]+))(?:[pP]([+-]?[0-9]+))?\Z")
_NAN_RE = re.compile(rb"nan\((.*)\)\Z")


def parse_real(fmt, tok):
    """commands.md 3.4 'Read'. Returns bits in fmt, or None (error)."""
    neg = tok.startswith(b"-")
    body = tok[1:] if neg else tok
    sign = fmt.sign if neg else 0
    if body == b"inf":
        return sign | fmt.exp_mask
    if body == b"nan":
        return sign | fmt.default_nan
    m = _NAN_RE.match(body)
    if m:
        v = parse_uint(m.group(1), (1 << 64) - 1)
        if v is None or v >= (1 << fmt.width) or not fmt.is_nan(v):
            return None
        if neg and (v & fmt.sign):
            return None
        return v | sign
    m = _HEX_RE.match(body)
    if m:
        ip = (m.group(1) or b"").decode()
        fp = (m.group(2) or m.group(3) or b"").decode()
        e = int(m.group(4) or b"0")
        mant = int(ip + fp or "0", 16)
        zero = mant == 0
        if zero:
            return sign
        e -= 4 * len(fp)
        if e > 100000:
            return None
        if e < -100000:
            return None
        fr = Fraction(mant) * Fraction(2) ** e
    elif _DEC_RE.match(body):
        s = body.decode()
        mant_part = re.split("[eE]", s)[0]
        zero = set(mant_part) <= set("0.")
        if zero:
            return sign
        d = float(s)  # correctly rounded binary64, for a range check
        if math.isinf(d) or d == 0.0:
            return None
        if fmt is F64:
            return sign | float_to_bits(d)
        fr = Fraction(s)
    else:
        return None
    r = fmt.round_fraction(fr)
    if r is None or r == 0:  # overflow, or a non-zero that rounds to zero
        return None
    if r == fmt.exp_mask:
        return None
    return sign | r


def parse_uint(tok, maxval):
    if re.match(rb"[0-9]+\Z", tok):
        v = int(tok)
    elif re.match(rb"0[xX][0-9a-fA-F]+\Z", tok):
        v = int(tok[2:], 16)
    else:
        return None
    return v if v <= maxval else None


def format_uint(v, maxval):
    return "0x%X" % v if v == maxval else "%d" % v


def format_name(b):
    out = ['"']
    for c in b:
        if c == 0x22:
            out.append('\\"')
        elif c == 0x5C:
            out.append("\\\\")
        elif c < 0x20 or c >= 0x7F:
            out.append("\\x%02X" % c)
        else:
            out.append(chr(c))
    out.append('"')
    return "".join(out)


# --- text form of one command (commands.md section 1) ------------------------

BLANKS = b" \t\r"


class ParseError(Exception):
    def __init__(self, column, message):
        super().__init__(message)
        self.column = column
        self.message = message


def _shown(tok):
    if len(tok) > 40:
        tok = tok[:40] + b"..."
    return tok.decode("latin-1")


def _token_end(line, pos):
    end = pos
    while end < len(line) and line[end] not in BLANKS and line[end] != 0x23:
        end += 1
    return end


def parse_command(line):
    """Parses one line. Returns (verb, {field: value}) or None for a blank line;
    raises ParseError with a 1-based column."""
    n = len(line)
    pos = 0
    while pos < n and line[pos] in BLANKS:
        pos += 1
    if pos >= n or line[pos] == 0x23:
        return None
    end = _token_end(line, pos)
    verb = line[pos:end].decode("latin-1")
    if verb not in COMMANDS:
        raise ParseError(pos + 1, 'expected a command verb (layer_create, vertex_set_xyz_real64, ...), found "%s"' % _shown(line[pos:end]))
    pos = end
    fields = {}
    for fname, ftype in COMMANDS[verb]:
        while pos < n and line[pos] in BLANKS:
            pos += 1
        what = "%s (%s)" % (fname, TYPE_TEXT[ftype])
        if pos >= n or line[pos] == 0x23:
            raise ParseError(pos + 1, "expected %s, found end of line" % what)
        if ftype == "name":
            if line[pos] != 0x22:
                end = _token_end(line, pos)
                raise ParseError(pos + 1, 'expected %s, found "%s"' % (what, _shown(line[pos:end])))
            value, pos = _parse_quoted(line, pos, fname)
            fields[fname] = value
            continue
        end = _token_end(line, pos)
        tok = line[pos:end]
        value = _convert(ftype, tok)
        if value is None:
            raise ParseError(pos + 1, 'expected %s, found "%s"' % (what, _shown(tok)))
        fields[fname] = value
        pos = end
    while pos < n and line[pos] in BLANKS:
        pos += 1
    if pos < n and line[pos] != 0x23:
        end = _token_end(line, pos)
        raise ParseError(pos + 1, 'expected end of line after %s, found "%s"' % (verb, _shown(line[pos:end])))
    return verb, fields


def _parse_quoted(line, pos, fname):
    bad = 'bad quoted %s: use \\" \\\\ or \\xHH escapes and close the quote on the same line' % fname
    out = bytearray()
    i = pos + 1
    n = len(line)
    while True:
        if i >= n:
            raise ParseError(n + 1, bad)
        c = line[i]
        if c == 0x22:
            i += 1
            if i < n and line[i] not in BLANKS and line[i] != 0x23:
                end = _token_end(line, i)
                raise ParseError(i + 1, 'expected a blank after the closing quote of %s, found "%s"' % (fname, _shown(line[i:end])))
            return bytes(out), i
        if c == 0x5C:
            nxt = line[i + 1:i + 2]
            if nxt in (b'"', b"\\"):
                out += nxt
                i += 2
                continue
            hexd = line[i + 2:i + 4]
            if nxt == b"x" and len(hexd) == 2 and re.match(rb"[0-9a-fA-F]{2}\Z", hexd):
                out.append(int(hexd, 16))
                i += 4
                continue
            raise ParseError(i + 1, bad)
        if c < 0x20:
            raise ParseError(i + 1, bad)
        out.append(c)
        i += 1


def _convert(ftype, tok):
    if ftype == "u8":
        return parse_uint(tok, U8_MAX)
    if ftype == "u16":
        return parse_uint(tok, U16_MAX)
    if ftype == "u32":
        return parse_uint(tok, U32_MAX)
    if ftype == "f32":
        return parse_real(F32, tok)
    if ftype == "f64":
        return parse_real(F64, tok)
    if ftype == "type":
        name = tok.decode("latin-1")
        return LAYER_TYPES[name] if name in LAYER_TYPES else parse_uint(tok, U8_MAX)
    if ftype == "format":
        name = tok.decode("latin-1")
        return REAL_FORMATS[name] if name in REAL_FORMATS else parse_uint(tok, U8_MAX)
    raise AssertionError(ftype)


# --- the node (commands.md section 4) ----------------------------------------

class Rejected(Exception):
    def __init__(self, reason):
        super().__init__(reason)
        self.reason = reason


def is_vertex_stack(t):
    return t < 128


def values_per_slot(t):
    return {VERTEX_XYZ: 3, POLY_CORNER_UINT32: 4, POLY_CORNER_REAL: 4}.get(t, 1)


def is_real_type(t):
    return t in (VERTEX_XYZ, VERTEX_REAL, POLY_CORNER_REAL, POLY_FACE_REAL)


def default_slot(layer):
    """commands.md 4.6: reals are f64 bits, uints ints; FACE_UINT8 keeps 8 bits."""
    t = layer.type
    if is_real_type(t):
        v = layer.def_real
    elif t == POLY_FACE_UINT8:
        v = layer.def_uint & 0xFF
    else:
        v = layer.def_uint
    return [v] * values_per_slot(t)


class Layer:
    def __init__(self, name, type_, def_uint, def_real):
        self.name = name
        self.type = type_
        self.def_uint = def_uint
        self.def_real = def_real  # f64 bits
        self.sub = None  # None, 0 (REAL32) or 1 (REAL64)
        self.slots = {}  # element id -> list of values


def valid_name(b):
    return len(b) <= 15 and b"\x00" not in b


def check_name(b):
    if not valid_name(b):
        raise Rejected("BAD_NAME")


def finite64(b):
    return F64.is_finite(b)


class Node:
    def __init__(self, max_cells=MAX_CELLS_PER_STACK):
        self.max_cells = max_cells
        self.layers = {0: Layer(b"vertex", VERTEX_XYZ, 0, 0), 1: Layer(b"polygon", POLY_CORNER_UINT32, 0, 0)}
        self.crease_vertex = (b"", 0)
        self.crease_edge = (b"", 0)
        self.bones = {}  # id -> dict of fields

    # helpers
    @property
    def vertices(self):
        return self.layers[0].slots

    @property
    def polygons(self):
        return self.layers[1].slots

    def stack_layers(self, vertex_stack):
        return [l for l in self.layers.values() if is_vertex_stack(l.type) == vertex_stack]

    def layer_by_name(self, name):
        for l in self.layers.values():
            if l.name == name:
                return l
        return None

    @staticmethod
    def pick(used, lo, hi):
        i = lo
        while i <= hi:
            if i not in used:
                return i
            i += 1
        raise Rejected("NO_FREE_ID")

    def apply(self, verb, f):
        """Applies one command; returns None (applied) or raises Rejected."""
        getattr(self, "do_" + verb)(f)

    # layers (4.4)
    def do_layer_create(self, f):
        lid, name, t = f["layer_id"], f["name"], f["type"]
        if name == b"":
            return self.do_layer_destroy(f)
        if lid in (0, 1):
            raise Rejected("BASE_LAYER")
        if t not in LAYER_TYPE_NAMES:
            raise Rejected("BAD_LAYER_TYPE")
        check_name(name)
        for oid, l in self.layers.items():
            if l.name == name and (lid == U16_MAX or oid != lid):
                raise Rejected("NAME_IN_USE")
        if lid == U16_MAX:
            lid = self.pick(self.layers, 2, 0xFFFE)
        old = self.layers.get(lid)
        vstack = is_vertex_stack(t)
        if old is None or is_vertex_stack(old.type) != vstack:
            live = len(self.vertices if vstack else self.polygons)
            if (len(self.stack_layers(vstack)) + 1) * max(live, 1) > self.max_cells:
                raise Rejected("LIMIT")
        if old is not None and old.type == t:
            old.name, old.def_uint, old.def_real = name, f["def_uint"], f["def_real"]
            return
        layer = Layer(name, t, f["def_uint"], f["def_real"])
        elements = self.vertices if vstack else self.polygons
        for e in elements:
            layer.slots[e] = default_slot(layer)
        self.layers[lid] = layer

    def do_layer_destroy(self, f):
        lid = f["layer_id"]
        if lid in (0, 1):
            raise Rejected("BASE_LAYER")
        if lid not in self.layers:
            raise Rejected("NO_SUCH_LAYER")
        del self.layers[lid]

    def do_layer_subscribe(self, f):
        if f["real_format"] > 1:  # wire alias (4.2): a format above REAL64 is the unsubscribe
            return self.do_layer_unsubscribe(f)
        l = self.layers.get(f["layer_id"])
        if l is None:
            raise Rejected("NO_SUCH_LAYER")
        l.sub = f["real_format"]

    def do_layer_unsubscribe(self, f):
        l = self.layers.get(f["layer_id"])
        if l is None:
            raise Rejected("NO_SUCH_LAYER")
        l.sub = None

    # slot writes (4.5)
    def write_slot(self, lid, eid, type_, values):
        l = self.layers.get(lid)
        if l is None:
            raise Rejected("NO_SUCH_LAYER")
        if l.type != type_:
            raise Rejected("WRONG_LAYER_TYPE")
        if eid not in l.slots:
            raise Rejected("NO_SUCH_VERTEX" if is_vertex_stack(type_) else "NO_SUCH_POLYGON")
        l.slots[eid] = list(values)

    # vertices
    def do_vertex_set_xyz_real32(self, f):
        xyz = [f["x"], f["y"], f["z"]]
        if FLT_MAX_BITS in xyz:
            return self.do_vertex_delete(f)
        self.set_xyz(f["layer_id"], f["vertex_id"], [widen_f32(b) for b in xyz])

    def do_vertex_set_xyz_real64(self, f):
        xyz = [f["x"], f["y"], f["z"]]
        if DBL_MAX_BITS in xyz:
            return self.do_vertex_delete(f)
        self.set_xyz(f["layer_id"], f["vertex_id"], xyz)

    def set_xyz(self, lid, vid, xyz):
        if lid != 0:
            return self.write_slot(lid, vid, VERTEX_XYZ, xyz)
        if not all(finite64(b) for b in xyz):
            raise Rejected("BAD_VALUE")
        if vid == U32_MAX:
            vid = self.pick(self.vertices, 0, 0xFFFFFFFE)
        if vid in self.vertices:
            self.vertices[vid] = xyz
            return
        layers = self.stack_layers(True)
        if (len(self.vertices) + 1) * len(layers) > self.max_cells:
            raise Rejected("LIMIT")
        for l in layers:
            l.slots[vid] = default_slot(l)
        self.vertices[vid] = xyz

    def do_vertex_delete(self, f):
        vid = f["vertex_id"]
        if vid not in self.vertices:
            raise Rejected("NO_SUCH_VERTEX")
        users = [p for p, c in self.polygons.items() if vid in c]
        for p in users:
            self.delete_polygon(p)
        for l in self.stack_layers(True):
            del l.slots[vid]

    def do_vertex_set_uint32(self, f):
        self.write_slot(f["layer_id"], f["vertex_id"], VERTEX_UINT32, [f["value"]])

    def do_vertex_set_real64(self, f):
        self.write_slot(f["layer_id"], f["vertex_id"], VERTEX_REAL, [f["value"]])

    def do_vertex_set_real32(self, f):
        self.write_slot(f["layer_id"], f["vertex_id"], VERTEX_REAL, [widen_f32(f["value"])])

    # polygons
    def do_polygon_set_corner_uint32(self, f):
        lid, pid = f["layer_id"], f["polygon_id"]
        v = [f["v[%d]" % i] for i in range(4)]
        if lid != 1:
            return self.write_slot(lid, pid, POLY_CORNER_UINT32, v)
        if v[0] == U32_MAX:
            return self.do_polygon_delete(f)
        if U32_MAX in v[:3]:
            raise Rejected("BAD_POLYGON")
        corners = v[:3] if v[3] == U32_MAX else v
        if len(set(corners)) != len(corners) and FAULT != "accept-duplicate-corners":
            raise Rejected("BAD_POLYGON")
        if any(c not in self.vertices for c in corners):
            raise Rejected("NO_SUCH_VERTEX")
        if pid == U32_MAX:
            pid = self.pick(self.polygons, 0, 0xFFFFFFFE)
        if pid in self.polygons:
            self.polygons[pid] = v
            return
        layers = self.stack_layers(False)
        if (len(self.polygons) + 1) * len(layers) > self.max_cells:
            raise Rejected("LIMIT")
        for l in layers:
            l.slots[pid] = default_slot(l)
        self.polygons[pid] = v

    def do_polygon_set_corner_real64(self, f):
        self.write_slot(f["layer_id"], f["polygon_id"], POLY_CORNER_REAL, [f["v[%d]" % i] for i in range(4)])

    def do_polygon_set_corner_real32(self, f):
        self.write_slot(f["layer_id"], f["polygon_id"], POLY_CORNER_REAL, [widen_f32(f["v[%d]" % i]) for i in range(4)])

    def do_polygon_delete(self, f):
        pid = f["polygon_id"]
        if pid not in self.polygons:
            raise Rejected("NO_SUCH_POLYGON")
        self.delete_polygon(pid)

    def delete_polygon(self, pid):
        for l in self.stack_layers(False):
            del l.slots[pid]

    def do_polygon_set_face_uint8(self, f):
        self.write_slot(f["layer_id"], f["polygon_id"], POLY_FACE_UINT8, [f["value"]])

    def do_polygon_set_face_uint32(self, f):
        self.write_slot(f["layer_id"], f["polygon_id"], POLY_FACE_UINT32, [f["value"]])

    def do_polygon_set_face_real64(self, f):
        self.write_slot(f["layer_id"], f["polygon_id"], POLY_FACE_REAL, [f["value"]])

    def do_polygon_set_face_real32(self, f):
        self.write_slot(f["layer_id"], f["polygon_id"], POLY_FACE_REAL, [widen_f32(f["value"])])

    # creases (4.7)
    def do_crease_set_vertex(self, f):
        check_name(f["layer"])
        self.crease_vertex = (f["layer"], f["def_crease"])

    def do_crease_set_edge(self, f):
        check_name(f["layer"])
        self.crease_edge = (f["layer"], f["def_crease"])

    # bones (4.8)
    def do_bone_create(self, f):
        bid = f["bone_id"]
        if f["weight"] == b"":
            return self.do_bone_destroy(f)
        for k in ("weight", "reference", "pos_label", "rot_label"):
            check_name(f[k])
        pos = [f["pos[%d]" % i] for i in range(3)]
        rot = [f["rot[%d]" % i] for i in range(4)]
        if not all(finite64(b) for b in pos + rot) or all((b & ~F64_SIGN) == 0 for b in rot):
            raise Rejected("BAD_VALUE")
        w = self.layer_by_name(f["weight"])
        if w is None or w.type not in (VERTEX_UINT32, VERTEX_REAL):
            raise Rejected("BAD_WEIGHT_LAYER")
        if f["reference"] != b"":
            r = self.layer_by_name(f["reference"])
            if r is None or r.type != VERTEX_UINT32:
                raise Rejected("BAD_REFERENCE_LAYER")
        if bid == U16_MAX:
            bid = self.pick(self.bones, 0, 0xFFFE)
        walk, seen = f["parent"], set()
        while True:
            if walk == bid:
                raise Rejected("BONE_CYCLE")
            if walk not in self.bones or walk in seen:
                break
            seen.add(walk)
            walk = self.bones[walk]["parent"]
        self.bones[bid] = {
            "weight": f["weight"], "reference": f["reference"], "parent": f["parent"],
            "pos": pos, "pos_label": f["pos_label"], "rot": rot, "rot_label": f["rot_label"],
        }

    def do_bone_destroy(self, f):
        if f["bone_id"] not in self.bones:
            raise Rejected("NO_SUCH_BONE")
        del self.bones[f["bone_id"]]

    # documents (section 6)
    def snapshot(self):
        r64 = lambda b: format_real(F64, b)
        out = ["vgc-snapshot 1"]
        for lid in sorted(self.layers):
            l = self.layers[lid]
            sub = "-" if l.sub is None else REAL_FORMAT_NAMES[l.sub]
            # commands.md 6.1: only the default the type uses is state; the other
            # (both, for layers 0 and 1) is "-". A FACE_UINT8 default is kept as
            # the uint8 its slots take.
            du, dr = "-", "-"
            if lid not in (0, 1):
                if is_real_type(l.type):
                    dr = r64(l.def_real)
                else:
                    du = format_uint(l.def_uint & 0xFF if l.type == POLY_FACE_UINT8 else l.def_uint, U32_MAX)
            out.append("layer %s %s %s %s %s %s" % (format_uint(lid, U16_MAX), format_name(l.name), LAYER_TYPE_NAMES[l.type],
                                                     du, dr, sub))
        out.append("crease_vertex %s %s" % (format_name(self.crease_vertex[0]), format_uint(self.crease_vertex[1], U32_MAX)))
        out.append("crease_edge %s %s" % (format_name(self.crease_edge[0]), format_uint(self.crease_edge[1], U32_MAX)))
        for vid in sorted(self.vertices):
            out.append("vertex %s %s" % (format_uint(vid, U32_MAX), " ".join(r64(b) for b in self.vertices[vid])))
        for pid in sorted(self.polygons):
            out.append("polygon %s %s" % (format_uint(pid, U32_MAX), " ".join(format_uint(c, U32_MAX) for c in self.polygons[pid])))
        for lid in sorted(self.layers):
            if lid in (0, 1):
                continue
            l = self.layers[lid]
            if is_real_type(l.type):
                fmt_v = r64
            elif l.type == POLY_FACE_UINT8:
                fmt_v = lambda v: format_uint(v, U8_MAX)
            else:
                fmt_v = lambda v: format_uint(v, U32_MAX)
            for e in sorted(l.slots):
                out.append("slot %s %s %s" % (format_uint(lid, U16_MAX), format_uint(e, U32_MAX), " ".join(fmt_v(v) for v in l.slots[e])))
        for bid in sorted(self.bones):
            b = self.bones[bid]
            out.append("bone %s %s %s %s %s %s %s %s" % (
                format_uint(bid, U16_MAX), format_name(b["weight"]), format_name(b["reference"]),
                format_uint(b["parent"], U16_MAX), " ".join(r64(x) for x in b["pos"]), format_name(b["pos_label"]),
                " ".join(r64(x) for x in b["rot"]), format_name(b["rot_label"])))
        out.append("end")
        return "\n".join(out) + "\n"

    def derived(self):
        out = ["vgc-derived 1"]
        vname, vconst = self.crease_vertex
        vl = self.layer_by_name(vname) if vname else None
        if vl is not None and vl.type != VERTEX_UINT32:
            vl = None
        for vid in sorted(self.vertices):
            c = vl.slots[vid][0] if vl else vconst
            out.append("vertex_crease %s %s" % (format_uint(vid, U32_MAX), format_uint(c, U32_MAX)))
        ename, econst = self.crease_edge
        el = self.layer_by_name(ename) if ename else None
        if el is not None and el.type != POLY_CORNER_UINT32:
            el = None
        for pid in sorted(self.polygons):
            n = 3 if self.polygons[pid][3] == U32_MAX else 4
            for i in range(n):
                c = el.slots[pid][i] if el else econst
                out.append("edge_crease %s %d %s" % (format_uint(pid, U32_MAX), i, format_uint(c, U32_MAX)))
        poses = self.bone_poses()
        for bid in sorted(self.bones):
            pos, rot = poses[bid]
            out.append("bone_pose %s %s" % (format_uint(bid, U16_MAX), " ".join(format_real(F64, float_to_bits(x)) for x in pos + rot)))
        out.append("end")
        return "\n".join(out) + "\n"

    def bone_poses(self):
        poses = {}
        for bid in sorted(self.bones):
            chain = []
            cur = bid
            while cur in self.bones and cur not in poses:
                chain.append(cur)
                cur = self.bones[cur]["parent"]
                if cur in chain:  # cannot happen (forest), but never loop
                    break
            for b in reversed(chain):
                bone = self.bones[b]
                pos = [bits_to_float(x) for x in bone["pos"]]
                rot = normalize([bits_to_float(x) for x in bone["rot"]])
                p = bone["parent"]
                if p in poses and p != b:
                    ppos, prot = poses[p]
                    wrot = normalize(qmul(prot, rot))
                    d = rotate(prot, pos)
                    wpos = [ppos[0] + d[0], ppos[1] + d[1], ppos[2] + d[2]]
                    poses[b] = (wpos, wrot)
                else:
                    poses[b] = (pos, rot)
        return poses


# --- quaternions (x, y, z, w), Hamilton product (commands.md 4.8) -----------

def qmul(a, b):
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return [
        aw * bx + ax * bw + ay * bz - az * by,
        aw * by - ax * bz + ay * bw + az * bx,
        aw * bz + ax * by - ay * bx + az * bw,
        aw * bw - ax * bx - ay * by - az * bz,
    ]


def normalize(q):
    # docs/commands.md 4.8: scaled as hypot scales (divide by the largest
    # |component| first), so any finite non-zero quaternion is the rotation
    # it is however tiny or huge its components; negated when the w sent is
    # below zero.
    if not all(math.isfinite(c) for c in q):
        return [0.0, 0.0, 0.0, 1.0]
    m = max(abs(c) for c in q)
    if m == 0.0:
        return [0.0, 0.0, 0.0, 1.0]
    r = [c / m for c in q]
    n = math.sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2] + r[3] * r[3])
    r = [c / n for c in r]
    if q[3] < 0:
        r = [-c for c in r]
    return r


def rotate(q, v):
    conj = [-q[0], -q[1], -q[2], q[3]]
    r = qmul(qmul(q, [v[0], v[1], v[2], 0.0]), conj)
    return r[:3]


# --- the exec protocol (adapters.md section 1) -------------------------------

def main():
    inp = sys.stdin.buffer
    out = sys.stdout.buffer
    node = Node()

    def answer(text):
        out.write(text if isinstance(text, bytes) else text.encode("latin-1"))
        out.flush()

    for raw in inp:
        line = raw[:-1] if raw.endswith(b"\n") else raw
        if line.startswith(b"?"):
            req = line.rstrip(b"\r")
            if req == b"?hello":
                answer("vgc-exec 1 vgc-python-cleanroom 1.0%s\n" % (" fault=" + FAULT if FAULT else ""))
            elif req == b"?reset":
                node = Node()
                answer("ok\n")
            elif req == b"?snapshot":
                answer(node.snapshot())
            elif req == b"?derived":
                answer(node.derived())
            elif req == b"?quit":
                return 0
            else:
                sys.stderr.write("unknown request %r\n" % req)
                answer(b"error unknown request " + req + b"\n")
            continue
        try:
            parsed = parse_command(line)
        except ParseError as e:
            answer("error line 1, column %d: %s\n" % (e.column, e.message.replace("\n", " ")))
            continue
        if parsed is None:
            answer("error line 1, column 1: expected a command, found an empty line or a comment\n")
            continue
        verb, fields = parsed
        try:
            node.apply(verb, fields)
            answer("ok\n")
        except Rejected as r:
            answer("rejected %s\n" % r.reason)
    return 0


if __name__ == "__main__":
    sys.exit(main())
