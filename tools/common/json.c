/* json.c — a recursive-descent JSON reader and the string and number
 * writers (json.h). */
#include "json.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "file_text.h"

typedef struct parser {
    const char* text;
    const char* p;
    const char* error;
    int depth;
} parser;

static void skip_space(parser* s) {
    while (*s->p == ' ' || *s->p == '\t' || *s->p == '\n' || *s->p == '\r') ++s->p;
}

static json_value* fail(parser* s, const char* error) {
    if (!s->error) s->error = error;
    return NULL;
}

static json_value* new_value(parser* s, json_type type) {
    json_value* value = calloc(1, sizeof *value);
    if (!value) return fail(s, "out of memory");
    value->type = type;
    return value;
}

static int hex_digit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

static size_t put_utf8(char* out, unsigned code) {
    if (code < 0x80) {
        out[0] = (char)code;
        return 1;
    }
    if (code < 0x800) {
        out[0] = (char)(0xC0 | code >> 6);
        out[1] = (char)(0x80 | (code & 0x3F));
        return 2;
    }
    if (code < 0x10000) {
        out[0] = (char)(0xE0 | code >> 12);
        out[1] = (char)(0x80 | (code >> 6 & 0x3F));
        out[2] = (char)(0x80 | (code & 0x3F));
        return 3;
    }
    out[0] = (char)(0xF0 | code >> 18);
    out[1] = (char)(0x80 | (code >> 12 & 0x3F));
    out[2] = (char)(0x80 | (code >> 6 & 0x3F));
    out[3] = (char)(0x80 | (code & 0x3F));
    return 4;
}

static int read_hex4(parser* s, unsigned* code) {
    *code = 0;
    for (int i = 0; i < 4; ++i) {
        const int digit = hex_digit(s->p[i]);
        if (digit < 0) return -1;
        *code = *code << 4 | (unsigned)digit;
    }
    s->p += 4;
    return 0;
}

/* Reads a string at s->p (on its opening quote) into a new buffer. */
static char* parse_string_text(parser* s) {
    ++s->p;
    const char* end = s->p;
    while (*end && *end != '"') end += (*end == '\\' && end[1]) ? 2 : 1;
    if (*end != '"') return (char*)fail(s, "a string is not closed");
    char* out = malloc((size_t)(end - s->p) + 1); /* escapes never grow the text */
    if (!out) return (char*)fail(s, "out of memory");
    size_t n = 0;
    while (s->p < end) {
        const char c = *s->p++;
        if ((unsigned char)c < 0x20) {
            free(out);
            return (char*)fail(s, "a control character inside a string");
        }
        if (c != '\\') {
            out[n++] = c;
            continue;
        }
        const char e = *s->p++;
        switch (e) {
            case '"': out[n++] = '"'; break;
            case '\\': out[n++] = '\\'; break;
            case '/': out[n++] = '/'; break;
            case 'b': out[n++] = '\b'; break;
            case 'f': out[n++] = '\f'; break;
            case 'n': out[n++] = '\n'; break;
            case 'r': out[n++] = '\r'; break;
            case 't': out[n++] = '\t'; break;
            case 'u': {
                unsigned code;
                if (read_hex4(s, &code) != 0) {
                    free(out);
                    return (char*)fail(s, "a bad \\u escape");
                }
                if (code >= 0xD800 && code < 0xDC00 && s->p[0] == '\\' && s->p[1] == 'u') {
                    unsigned low;
                    s->p += 2;
                    if (read_hex4(s, &low) != 0 || low < 0xDC00 || low >= 0xE000) {
                        free(out);
                        return (char*)fail(s, "a bad surrogate pair");
                    }
                    code = 0x10000 + ((code - 0xD800) << 10) + (low - 0xDC00);
                }
                n += put_utf8(out + n, code);
                break;
            }
            default:
                free(out);
                return (char*)fail(s, "a bad escape in a string");
        }
    }
    out[n] = 0;
    ++s->p;
    return out;
}

static json_value* parse_value(parser* s);

static json_value* parse_container(parser* s, json_type type) {
    const char close = type == JSON_ARRAY ? ']' : '}';
    json_value* container = new_value(s, type);
    if (!container) return NULL;
    if (++s->depth > 64) {
        json_free(container);
        return fail(s, "nested too deep");
    }
    ++s->p;
    skip_space(s);
    json_value** tail = &container->child;
    if (*s->p == close) {
        ++s->p;
        --s->depth;
        return container;
    }
    for (;;) {
        char* key = NULL;
        if (type == JSON_OBJECT) {
            skip_space(s);
            if (*s->p != '"') {
                json_free(container);
                return fail(s, "expected a member name in quotes");
            }
            key = parse_string_text(s);
            if (!key) {
                json_free(container);
                return NULL;
            }
            skip_space(s);
            if (*s->p != ':') {
                free(key);
                json_free(container);
                return fail(s, "expected ':' after a member name");
            }
            ++s->p;
        }
        json_value* element = parse_value(s);
        if (!element) {
            free(key);
            json_free(container);
            return NULL;
        }
        element->key = key;
        *tail = element;
        tail = &element->next;
        ++container->count;
        skip_space(s);
        if (*s->p == ',') {
            ++s->p;
            continue;
        }
        if (*s->p == close) {
            ++s->p;
            --s->depth;
            return container;
        }
        json_free(container);
        return fail(s, type == JSON_ARRAY ? "expected ',' or ']'" : "expected ',' or '}'");
    }
}

static json_value* parse_value(parser* s) {
    skip_space(s);
    const char c = *s->p;
    if (c == '{') return parse_container(s, JSON_OBJECT);
    if (c == '[') return parse_container(s, JSON_ARRAY);
    if (c == '"') {
        char* text = parse_string_text(s);
        if (!text) return NULL;
        json_value* value = new_value(s, JSON_STRING);
        if (!value) {
            free(text);
            return NULL;
        }
        value->string = text;
        return value;
    }
    static const struct {
        const char* word;
        json_type type;
        double number;
    } words[] = {{"true", JSON_BOOL, 1}, {"false", JSON_BOOL, 0}, {"null", JSON_NULL, 0}};
    for (size_t i = 0; i < sizeof words / sizeof words[0]; ++i) {
        const size_t length = strlen(words[i].word);
        if (strncmp(s->p, words[i].word, length) == 0) {
            s->p += length;
            json_value* value = new_value(s, words[i].type);
            if (value) value->number = words[i].number;
            return value;
        }
    }
    if (c == '-' || (c >= '0' && c <= '9')) {
        char* end = NULL;
        const double number = strtod(s->p, &end);
        if (end == s->p) return fail(s, "a bad number");
        s->p = end;
        json_value* value = new_value(s, JSON_NUMBER);
        if (value) value->number = number;
        return value;
    }
    return fail(s, c ? "unexpected character" : "unexpected end of the text");
}

json_value* json_parse(const char* text, const char** error, size_t* offset) {
    parser s = {text, text, NULL, 0};
    json_value* value = parse_value(&s);
    if (value) {
        skip_space(&s);
        if (*s.p) {
            json_free(value);
            value = fail(&s, "text after the end of the value");
        }
    }
    if (!value) {
        if (error) *error = s.error;
        if (offset) *offset = (size_t)(s.p - text);
    }
    return value;
}

json_value* json_read_file(const char* path, const char** error) {
    char* text = file_text_read(path, NULL);
    if (!text) {
        *error = "cannot read the file";
        return NULL;
    }
    json_value* value = json_parse(text, error, NULL);
    free(text);
    return value;
}

void json_free(json_value* value) {
    while (value) {
        json_value* next = value->next;
        json_free(value->child);
        free(value->string);
        free(value->key);
        free(value);
        value = next;
    }
}

const json_value* json_get(const json_value* object, const char* key) {
    if (!object || object->type != JSON_OBJECT) return NULL;
    for (const json_value* member = object->child; member; member = member->next)
        if (strcmp(member->key, key) == 0) return member;
    return NULL;
}

const char* json_get_string(const json_value* object, const char* key, const char* fallback) {
    const json_value* member = json_get(object, key);
    return member && member->type == JSON_STRING ? member->string : fallback;
}

double json_get_number(const json_value* object, const char* key, double fallback) {
    const json_value* member = json_get(object, key);
    return member && (member->type == JSON_NUMBER || member->type == JSON_BOOL) ? member->number : fallback;
}

void json_write_string(FILE* out, const char* text) {
    if (!text) {
        fputs("null", out);
        return;
    }
    fputc('"', out);
    for (const unsigned char* p = (const unsigned char*)text; *p; ++p) {
        if (*p == '"' || *p == '\\') fprintf(out, "\\%c", *p);
        else if (*p == '\n') fputs("\\n", out);
        else if (*p == '\t') fputs("\\t", out);
        else if (*p < 0x20) fprintf(out, "\\u%04x", *p);
        else fputc(*p, out);
    }
    fputc('"', out);
}

void json_write_number(FILE* out, double number) {
    if (!isfinite(number)) fputs("null", out);
    else if (number == floor(number) && fabs(number) < 1e15) fprintf(out, "%.0f", number);
    else fprintf(out, "%.17g", number);
}
