/* digest.h: the report's input digest, the SHA-256 of the scenario text
 * (FIPS 180-4), printed beside the scenario as run (private to
 * src/report). */
#ifndef WALLLOAD_REPORT_DIGEST_H
#define WALLLOAD_REPORT_DIGEST_H

#include <stddef.h>
#include <stdint.h>

/* Digest of len bytes at data into out[32]. */
void wl_report_sha256(const void *data, size_t len, uint8_t out[32]);

/* The same as 64 lower-case hex digits and a NUL into hex[65]. */
void wl_report_sha256_hex(const void *data, size_t len, char hex[65]);

#endif
