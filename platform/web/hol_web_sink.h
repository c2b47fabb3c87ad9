/* hol_web_sink.h - the session's sink (core/hol_sink.h) in the browser: the
 * page's store of named byte streams (platform/web/store.js), kept in
 * IndexedDB and offered for download.
 *
 * Contract
 * - One flat folder for the page: every session's logs go to it with
 *   desc.append (attempts numbered on across visits, summary.csv one row
 *   per attempt of every visit, an attempt a closed tab left unfinished
 *   finished `killed` at the next visit), recordings beside them as
 *   session-ID.rec (session-ID.rec.live while the session runs).
 * - open, write, close, rename, remove, read and list are the store's;
 *   flush hands the bytes written since the last flush to IndexedDB in one
 *   transaction (durable or not: the browser has no fsync; a tab closed in
 *   the milliseconds before the transaction commits may lose that second
 *   of rows, never an earlier one); rename is one transaction, so atomic.
 * - why: the store's last failure ("QuotaExceededError ...").
 * - hol_web_sink_meta: the session's metadata from the browser's clock
 *   (UTC) and crypto.getRandomValues: id YYYYMMDDTHHMMSSZ-XXXXXXXX as the
 *   desktop's, the participant given ("" none).
 */
#ifndef HOL_WEB_SINK_H
#define HOL_WEB_SINK_H

#include "../../core/hol_rec.h"
#include "../../core/hol_sink.h"

const hol_sink *hol_web_sink(void);
void hol_web_sink_meta(hol_rec_meta *m, const char *participant);

#endif
