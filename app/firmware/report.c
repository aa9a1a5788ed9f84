/* report.c - report lines on the console, as 'T' records (sink.h), the
 * same on every board whatever its display. */
#include "port.h"
#include "sink.h"

void report_text(const char *text)
{
    uint16_t n = 0;
    while (text[n] != '\0')
        n++;
    uint8_t hdr[3] = { 'T', (uint8_t)n, (uint8_t)(n >> 8) };
    port_write(hdr, sizeof hdr);
    port_write(text, n);
}

void report_value(const char *key, uint64_t value)
{
    char digits[20];
    char *d = digits + sizeof digits;
    do {
        *--d = (char)('0' + value % 10);
        value /= 10;
    } while (value != 0);
    uint16_t k = 0;
    while (key[k] != '\0')
        k++;
    uint16_t n = (uint16_t)(k + 1 + (digits + sizeof digits - d));
    uint8_t hdr[3] = { 'T', (uint8_t)n, (uint8_t)(n >> 8) };
    port_write(hdr, sizeof hdr);
    port_write(key, k);
    port_write(" ", 1);
    port_write(d, (size_t)(digits + sizeof digits - d));
}
