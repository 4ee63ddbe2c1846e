/* c_host_text.c — the text form of one command line (vgc docs/commands.md
 * section 1: tokens, blanks, comments, quoted names; section 2: verbs and
 * their fields) and of values (section 3: unsigned integers, layer types,
 * real formats, reals bit for bit, quoted names).
 *
 * Reals are read with strtod/strtof (correctly rounded in glibc) after the
 * token has been checked against the grammar of section 3.4, and printed
 * in the shortest form that reads back to the same bits: the fewest
 * significant digits, from printf's correctly rounded "%.*e".
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "c_host.h"

#define F64_SIGN 0x8000000000000000ull
#define F64_EXP 0x7FF0000000000000ull
#define F64_DEFAULT_NAN 0x7FF8000000000000ull
#define F32_SIGN 0x80000000ull
#define F32_EXP 0x7F800000ull
#define F32_DEFAULT_NAN 0x7FC00000ull

static uint64_t bits_of_double(double d) {
  uint64_t b;
  memcpy(&b, &d, sizeof b);
  return b;
}

static double double_of_bits(uint64_t b) {
  double d;
  memcpy(&d, &b, sizeof d);
  return d;
}

uint64_t ch_widen_real32(uint32_t bits) {
  const uint64_t sign = (uint64_t)(bits >> 31) << 63;
  const uint32_t exponent = (bits >> 23) & 0xFF;
  const uint64_t mantissa = bits & 0x7FFFFF;
  if (exponent == 0xFF && mantissa != 0) /* NaN: quiet bit set, payload on top */
    return sign | F64_EXP | (1ull << 51) | (mantissa << 29);
  float f;
  memcpy(&f, &bits, sizeof f);
  return bits_of_double((double)f); /* exact for every other value */
}

/* ---- values: reading (section 3) ------------------------------------- */

static int is_digit(char c) { return c >= '0' && c <= '9'; }

static int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

/* 3.1: decimal digits, or 0x/0X and hex digits; at most max. */
static int parse_uint(const char* s, size_t n, uint64_t max, uint64_t* out) {
  uint64_t v = 0;
  if (n > 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X')) {
    for (size_t i = 2; i < n; ++i) {
      const int d = hex_value(s[i]);
      if (d < 0 || v > (max - (uint64_t)d) / 16) return 0;
      v = v * 16 + (uint64_t)d;
    }
  } else {
    if (n == 0) return 0;
    for (size_t i = 0; i < n; ++i) {
      if (!is_digit(s[i])) return 0;
      const uint64_t d = (uint64_t)(s[i] - '0');
      if (v > (max - d) / 10) return 0;
      v = v * 10 + d;
    }
  }
  *out = v;
  return 1;
}

/* Checks s[0..n) against the decimal or hex-float grammar of 3.4 (no sign);
 * *zero says whether every mantissa digit is 0. */
static int real_syntax(const char* s, size_t n, int* zero) {
  size_t i = 0, digits = 0;
  int hex = 0;
  *zero = 1;
  if (n > 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X')) {
    hex = 1;
    i = 2;
  }
  for (; i < n && (hex ? hex_value(s[i]) >= 0 : is_digit(s[i])); ++i, ++digits)
    if (s[i] != '0') *zero = 0;
  if (i < n && s[i] == '.') {
    ++i;
    for (; i < n && (hex ? hex_value(s[i]) >= 0 : is_digit(s[i])); ++i, ++digits)
      if (s[i] != '0') *zero = 0;
  }
  if (digits == 0) return 0;
  if (i < n && (hex ? (s[i] == 'p' || s[i] == 'P') : (s[i] == 'e' || s[i] == 'E'))) {
    ++i;
    if (i < n && (s[i] == '+' || s[i] == '-')) ++i;
    size_t exponent_digits = 0;
    for (; i < n && is_digit(s[i]); ++i) ++exponent_digits;
    if (exponent_digits == 0) return 0;
  }
  return i == n;
}

/* 3.4 "Read": a real32 (f32 set) or real64 token to its bit pattern. */
static int parse_real(const char* s, size_t n, int f32, uint64_t* out) {
  const uint64_t sign_bit = f32 ? F32_SIGN : F64_SIGN;
  const uint64_t exp_mask = f32 ? F32_EXP : F64_EXP;
  const uint64_t width_mask = f32 ? 0xFFFFFFFFull : ~0ull;
  uint64_t sign = 0;
  if (n > 0 && s[0] == '-') {
    sign = sign_bit;
    ++s;
    --n;
  }
  if (n == 3 && memcmp(s, "inf", 3) == 0) {
    *out = sign | exp_mask;
    return 1;
  }
  if (n == 3 && memcmp(s, "nan", 3) == 0) {
    *out = sign | (f32 ? F32_DEFAULT_NAN : F64_DEFAULT_NAN);
    return 1;
  }
  if (n > 5 && memcmp(s, "nan(", 4) == 0 && s[n - 1] == ')') {
    uint64_t v;
    if (!parse_uint(s + 4, n - 5, width_mask, &v)) return 0;
    const int is_nan = (v & exp_mask) == exp_mask && (v & ~(exp_mask | sign_bit) & width_mask) != 0;
    if (!is_nan || (sign && (v & sign_bit))) return 0;
    *out = v | sign;
    return 1;
  }
  int zero;
  if (!real_syntax(s, n, &zero)) return 0;
  if (zero) {
    *out = sign;
    return 1;
  }
  char buf[512];
  if (n >= sizeof buf) { /* keep it simple: no canonical real is this long */
    return 0;
  }
  memcpy(buf, s, n);
  buf[n] = '\0';
  char* end;
  uint64_t bits;
  if (f32) {
    const float f = strtof(buf, &end);
    uint32_t b32;
    memcpy(&b32, &f, sizeof b32);
    bits = b32;
  } else {
    bits = bits_of_double(strtod(buf, &end));
  }
  if (end != buf + n) return 0;
  /* too large (rounds to infinity) or too small (rounds to zero): errors */
  if ((bits & exp_mask) == exp_mask || bits == 0) return 0;
  *out = sign | bits;
  return 1;
}

static const char* const LAYER_TYPE_NAMES[] = {"VERTEX_XYZ", "VERTEX_UINT32", "VERTEX_REAL"};
static const char* const POLYGON_TYPE_NAMES[] = {"POLYGON_CORNER_UINT32", "POLYGON_CORNER_REAL",
                                                 "POLYGON_FACE_UINT8", "POLYGON_FACE_UINT32",
                                                 "POLYGON_FACE_REAL"};

/* 3.2: one of the eight names or a u8. */
static int parse_layer_type(const char* s, size_t n, uint64_t* out) {
  for (int i = 0; i < 3; ++i)
    if (strlen(LAYER_TYPE_NAMES[i]) == n && memcmp(s, LAYER_TYPE_NAMES[i], n) == 0) {
      *out = (uint64_t)i;
      return 1;
    }
  for (int i = 0; i < 5; ++i)
    if (strlen(POLYGON_TYPE_NAMES[i]) == n && memcmp(s, POLYGON_TYPE_NAMES[i], n) == 0) {
      *out = 128u + (uint64_t)i;
      return 1;
    }
  return parse_uint(s, n, 0xFF, out);
}

/* 3.3: REAL32, REAL64 or a u8. */
static int parse_real_format(const char* s, size_t n, uint64_t* out) {
  if (n == 6 && memcmp(s, "REAL32", 6) == 0) {
    *out = 0;
    return 1;
  }
  if (n == 6 && memcmp(s, "REAL64", 6) == 0) {
    *out = 1;
    return 1;
  }
  return parse_uint(s, n, 0xFF, out);
}

/* ---- values: printing (section 3) ------------------------------------ */

void ch_format_uint(uint64_t value, uint64_t all_ones, char* out) {
  if (value == all_ones)
    sprintf(out, "0x%llX", (unsigned long long)value);
  else
    sprintf(out, "%llu", (unsigned long long)value);
}

/* The shortest significant digits that read back to v (finite, > 0):
 * digits[] without trailing zeros, and the decimal exponent of the first. */
static void shortest_digits(double v, char* digits, int* exponent) {
  char buf[40];
  for (int precision = 0; precision < 17; ++precision) {
    /* The correctly rounded candidate, then (for the lopsided interval
     * at a power of two) the next one up, as the shortest form may be it. */
    for (int up = 0; up < 2; ++up) {
      snprintf(buf, sizeof buf, "%.*e", precision, v);
      char* e = strchr(buf, 'e');
      int exp10 = atoi(e + 1);
      size_t n = 0;
      for (char* p = buf; p < e; ++p)
        if (is_digit(*p)) digits[n++] = *p;
      digits[n] = '\0';
      if (up) { /* digits + 1 in the last place */
        size_t i = n;
        while (i > 0 && digits[i - 1] == '9') digits[--i] = '0';
        if (i == 0) {
          memmove(digits + 1, digits, n + 1);
          digits[0] = '1';
          digits[n] = '\0'; /* one more digit would be a trailing zero */
          ++exp10;
        } else {
          digits[i - 1]++;
        }
        snprintf(buf, sizeof buf, "%c.%se%d", digits[0], digits + 1, exp10);
      }
      if (strtod(buf, NULL) == v) {
        size_t len = strlen(digits);
        while (len > 1 && digits[len - 1] == '0') digits[--len] = '\0';
        *exponent = exp10;
        return;
      }
    }
  }
  snprintf(buf, sizeof buf, "%.16e", v); /* 17 digits always read back */
  char* e = strchr(buf, 'e');
  size_t n = 0;
  for (char* p = buf; p < e; ++p)
    if (is_digit(*p)) digits[n++] = *p;
  while (n > 1 && digits[n - 1] == '0') --n;
  digits[n] = '\0';
  *exponent = atoi(e + 1);
}

/* 3.4 "Printed": inf, nan, nan(0x<16 hex digits>), or the shortest of the
 * plain and scientific forms of the shortest digits (plain on a tie). */
void ch_format_real64(uint64_t bits, char* out) {
  const char* sign = (bits & F64_SIGN) ? "-" : "";
  const uint64_t magnitude = bits & ~F64_SIGN;
  if (magnitude > F64_EXP) { /* NaN */
    if (bits == F64_DEFAULT_NAN)
      strcpy(out, "nan");
    else
      sprintf(out, "nan(0x%016llX)", (unsigned long long)bits);
    return;
  }
  if (magnitude == F64_EXP) {
    sprintf(out, "%sinf", sign);
    return;
  }
  if (magnitude == 0) {
    sprintf(out, "%s0", sign);
    return;
  }
  const double v = double_of_bits(magnitude);
  char digits[24];
  int x;
  shortest_digits(v, digits, &x);
  const int n = (int)strlen(digits);
  char scientific[40], plain[400];
  sprintf(scientific, "%c%s%se%c%02d", digits[0], n > 1 ? "." : "", digits + 1, x < 0 ? '-' : '+', x < 0 ? -x : x);
  if (x >= n - 1) { /* an integer: all its exact digits */
    snprintf(plain, sizeof plain, "%.0f", v);
  } else if (x >= 0) {
    snprintf(plain, sizeof plain, "%.*s.%s", x + 1, digits, digits + x + 1);
  } else { /* 0.000ddd: -x - 1 zeros after the point */
    char* p = plain;
    *p++ = '0';
    *p++ = '.';
    for (int i = 0; i < -x - 1; ++i) *p++ = '0';
    strcpy(p, digits);
  }
  sprintf(out, "%s%s", sign, strlen(plain) <= strlen(scientific) ? plain : scientific);
}

void ch_format_name(const ch_name* name, char* out) {
  char* p = out;
  *p++ = '"';
  for (size_t i = 0; i < name->len && i < sizeof name->bytes; ++i) {
    const unsigned char c = name->bytes[i];
    if (c == '"' || c == '\\') {
      *p++ = '\\';
      *p++ = (char)c;
    } else if (c < 0x20 || c >= 0x7F) {
      p += sprintf(p, "\\x%02X", c);
    } else {
      *p++ = (char)c;
    }
  }
  *p++ = '"';
  *p = '\0';
}

/* ---- command lines (sections 1 and 2) -------------------------------- */

/* Field kinds: b u8, h u16, u u32, f real32, d real64, n name, t layer
 * type, m real format. One letter per field, in order. */
static const struct {
  const char* verb;
  const char* fields;
} VERBS[CH_VERB_COUNT] = {
    [CH_LAYER_CREATE] = {"layer_create", "hntud"},
    [CH_LAYER_DESTROY] = {"layer_destroy", "h"},
    [CH_LAYER_SUBSCRIBE] = {"layer_subscribe", "hm"},
    [CH_LAYER_UNSUBSCRIBE] = {"layer_unsubscribe", "h"},
    [CH_VERTEX_SET_XYZ_REAL32] = {"vertex_set_xyz_real32", "hufff"},
    [CH_VERTEX_SET_XYZ_REAL64] = {"vertex_set_xyz_real64", "huddd"},
    [CH_VERTEX_DELETE] = {"vertex_delete", "u"},
    [CH_VERTEX_SET_UINT32] = {"vertex_set_uint32", "huu"},
    [CH_VERTEX_SET_REAL64] = {"vertex_set_real64", "hud"},
    [CH_VERTEX_SET_REAL32] = {"vertex_set_real32", "huf"},
    [CH_POLYGON_SET_CORNER_UINT32] = {"polygon_set_corner_uint32", "huuuuu"},
    [CH_POLYGON_SET_CORNER_REAL64] = {"polygon_set_corner_real64", "hudddd"},
    [CH_POLYGON_SET_CORNER_REAL32] = {"polygon_set_corner_real32", "huffff"},
    [CH_POLYGON_DELETE] = {"polygon_delete", "u"},
    [CH_POLYGON_SET_FACE_UINT8] = {"polygon_set_face_uint8", "hub"},
    [CH_POLYGON_SET_FACE_UINT32] = {"polygon_set_face_uint32", "huu"},
    [CH_POLYGON_SET_FACE_REAL64] = {"polygon_set_face_real64", "hud"},
    [CH_POLYGON_SET_FACE_REAL32] = {"polygon_set_face_real32", "huf"},
    [CH_CREASE_SET_VERTEX] = {"crease_set_vertex", "nu"},
    [CH_CREASE_SET_EDGE] = {"crease_set_edge", "nu"},
    [CH_BONE_CREATE] = {"bone_create", "hnnhdddnddddn"},
    [CH_BONE_DESTROY] = {"bone_destroy", "h"},
};

static const char* kind_text(char kind) {
  switch (kind) {
    case 'b': return "uint8";
    case 'h': return "uint16";
    case 'u': return "uint32";
    case 'f': return "real32";
    case 'd': return "real64";
    case 'n': return "quoted name";
    case 't': return "layer type";
    default: return "real format";
  }
}

static int is_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

/* End of the token starting at s[i]: the next blank, '#' or the end. */
static size_t token_end(const char* s, size_t i) {
  while (s[i] != '\0' && !is_blank(s[i]) && s[i] != '#') ++i;
  return i;
}

/* 3.5: a quoted name at s[*i] (which is '"'). Returns 0 with *column set
 * on an error. */
static int parse_quoted(const char* s, size_t* i, ch_name* name, size_t* column) {
  size_t p = *i + 1;
  name->len = 0;
  for (;;) {
    const unsigned char c = (unsigned char)s[p];
    int byte;
    if (c == '\0') {
      *column = p + 1;
      return 0;
    }
    if (c == '"') break;
    if (c < 0x20) {
      *column = p + 1;
      return 0;
    }
    if (c == '\\') {
      if (s[p + 1] == '"' || s[p + 1] == '\\') {
        byte = s[p + 1];
        p += 2;
      } else if (s[p + 1] == 'x' && hex_value(s[p + 2]) >= 0 && hex_value(s[p + 3]) >= 0) {
        byte = hex_value(s[p + 2]) * 16 + hex_value(s[p + 3]);
        p += 4;
      } else {
        *column = p + 1;
        return 0;
      }
    } else {
      byte = c;
      ++p;
    }
    if (name->len < sizeof name->bytes) name->bytes[name->len] = (unsigned char)byte;
    name->len++;
  }
  ++p; /* the closing quote must be followed by a blank, '#' or the end */
  if (s[p] != '\0' && !is_blank(s[p]) && s[p] != '#') {
    *column = p + 1;
    return 0;
  }
  *i = p;
  return 1;
}

int ch_parse_command(const char* s, ch_command* cmd, char* error, size_t error_size) {
  size_t i = 0;
  while (is_blank(s[i])) ++i;
  if (s[i] == '\0' || s[i] == '#') {
    snprintf(error, error_size, "line 1, column %zu: expected a command, found an empty line or a comment", i + 1);
    return 0;
  }
  size_t end = token_end(s, i);
  int verb = -1;
  for (int v = 0; v < CH_VERB_COUNT; ++v)
    if (strlen(VERBS[v].verb) == end - i && memcmp(s + i, VERBS[v].verb, end - i) == 0) verb = v;
  if (verb < 0) {
    snprintf(error, error_size, "line 1, column %zu: expected a command verb, found \"%.*s\"", i + 1,
             (int)(end - i > 40 ? 40 : end - i), s + i);
    return 0;
  }
  memset(cmd, 0, sizeof *cmd);
  cmd->verb = (enum ch_verb)verb;
  i = end;
  const char* kinds = VERBS[verb].fields;
  for (size_t f = 0; kinds[f] != '\0'; ++f) {
    const char kind = kinds[f];
    while (is_blank(s[i])) ++i;
    if (s[i] == '\0' || s[i] == '#') {
      snprintf(error, error_size, "line 1, column %zu: expected field %zu (%s), found end of line", i + 1, f + 1,
               kind_text(kind));
      return 0;
    }
    if (kind == 'n') {
      size_t column = i + 1;
      if (s[i] != '"' || !parse_quoted(s, &i, &cmd->name[f], &column)) {
        snprintf(error, error_size, "line 1, column %zu: expected field %zu (%s)", column, f + 1, kind_text(kind));
        return 0;
      }
      continue;
    }
    end = token_end(s, i);
    const size_t n = end - i;
    int ok;
    switch (kind) {
      case 'b': ok = parse_uint(s + i, n, 0xFF, &cmd->value[f]); break;
      case 'h': ok = parse_uint(s + i, n, 0xFFFF, &cmd->value[f]); break;
      case 'u': ok = parse_uint(s + i, n, 0xFFFFFFFF, &cmd->value[f]); break;
      case 'f': ok = parse_real(s + i, n, 1, &cmd->value[f]); break;
      case 'd': ok = parse_real(s + i, n, 0, &cmd->value[f]); break;
      case 't': ok = parse_layer_type(s + i, n, &cmd->value[f]); break;
      default: ok = parse_real_format(s + i, n, &cmd->value[f]); break;
    }
    if (!ok) {
      snprintf(error, error_size, "line 1, column %zu: expected field %zu (%s), found \"%.*s\"", i + 1, f + 1,
               kind_text(kind), (int)(n > 40 ? 40 : n), s + i);
      return 0;
    }
    i = end;
  }
  while (is_blank(s[i])) ++i;
  if (s[i] != '\0' && s[i] != '#') {
    snprintf(error, error_size, "line 1, column %zu: expected end of line after %s", i + 1, VERBS[verb].verb);
    return 0;
  }
  return 1;
}
