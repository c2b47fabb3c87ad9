# report_referee.R - R (base only, no packages) as the referee of a
# report's participant-level statistics (docs/report.md "Participant-level
# statistics"; tests/cli_report_r.sh runs it): from trials.csv alone it
# recomputes every participant's mean per condition (the trials whose
# `excluded` is empty), then per condition and measure n, trials, mean, SD,
# the between-subjects 95 % CI (qt on the participants' means) and the
# within-subjects one (Cousineau 2005, Morey 2008: each complete
# participant's value less their mean plus the grand mean, the half width
# times sqrt(J / (J - 1))); for each pair of a study's conditions the
# paired difference, its CI, d_z and the factors the two differ in; for
# each pair of a factor's levels (main effects: a level's value the mean
# of its conditions) the same. Every figure of participants_stats.csv,
# paired.csv and effects.csv must agree to 1e-9, every row R expects must
# be there and no other; the questionnaires' rows of participants_stats.csv
# (SSQ and TLX scores per condition and `study`; their pairs and main
# effects, of those asked per condition) from scores.csv alike, its
# `excluded` scores (of a duplicate or restarted run) left out.
# Usage: Rscript report_referee.R REPORT_DIR
# [--include-restarted] (the report's option: trials excluded as duplicate
# or restarted count too). Exit 0 when all agree ("R referee: N figures
# agree"), else 1 naming each disagreement.
args <- commandArgs(trailingOnly = TRUE)
dir <- args[1]
rd <- function(f) read.csv(file.path(dir, f), stringsAsFactors = FALSE, na.strings = "",
                           colClasses = c(study = "character", condition = "character"))
tr <- read.csv(file.path(dir, "trials.csv"), stringsAsFactors = FALSE, na.strings = "",
               colClasses = c(study = "character", condition = "character",
                              participant = "character", excluded = "character"))
ps <- rd("participants_stats.csv")
pd <- read.csv(file.path(dir, "paired.csv"), stringsAsFactors = FALSE, na.strings = "",
               colClasses = c(study = "character", condition_a = "character",
                              condition_b = "character", differ = "character"))
ef <- read.csv(file.path(dir, "effects.csv"), stringsAsFactors = FALSE, na.strings = NULL,
               colClasses = c(study = "character", level_a = "character",
                              level_b = "character"))
tr$study[is.na(tr$study)] <- ""
ps$study[is.na(ps$study)] <- ""
pd$study[is.na(pd$study)] <- ""
counted <- if ("--include-restarted" %in% args) c("duplicate", "restarted") else character(0)
inc <- tr[is.na(tr$excluded) | tr$excluded %in% counted, ]
measures <- c("steps", "efficiency", "time", "error_true", "error_flat")
tol <- 1e-9
checked <- 0
wrong <- character(0)
same <- function(what, got, want) {
    ok <- (is.na(got) && is.na(want)) ||
        (!is.na(got) && !is.na(want) && abs(got - want) <= tol)
    checked <<- checked + 1
    if (!ok) wrong <<- c(wrong, sprintf("%s: report %s, R %s", what, format(got, digits = 17),
                                        format(want, digits = 17)))
}
ci <- function(x, k = 1) {
    n <- length(x)
    if (n < 2) return(c(NA, NA))
    h <- qt(0.975, n - 1) * k * sd(x) / sqrt(n)
    c(mean(x) - h, mean(x) + h)
}
# d_z: empty for n under 2 or no spread (an SD of 0 or under 1e-9 of the
# mean's magnitude: equal differences but for rounding)
dz_of <- function(dd) {
    s <- if (length(dd) > 1) sd(dd) else 0
    if (s <= 0 || s <= 1e-9 * abs(mean(dd))) NA else mean(dd) / s
}
seen <- 0
seen_pairs <- 0
seen_effects <- 0
factors <- c("q", "room", "cell", "cues", "minimap")
# a factor's value as trials.csv writes it ("" for none)
level_text <- function(x) ifelse(is.na(x), "", as.character(x))
# the main effects and the paired differences of one study's measure m:
# pm the participants' means (participant x condition, the conditions cm in
# the report's order), complete its rows with a mean in each, d the
# study's included trials (a condition's factors its first trial's),
# small the study of at most 32 conditions (main effects)
effects_and_pairs <- function(st, m, cm, pm, complete, d, small) {
    J <- length(cm)
    if (J < 2) return(invisible())
    # main effects: each factor's levels (the conditions' first trials),
    # a level's value the mean of its conditions for the complete
    # participants, each pair of levels A - B
    if (small && nrow(complete)) for (k in factors) {
        lv <- sapply(cm, function(cc) level_text(d[d$condition == cc, k][1]))
        L <- unique(lv)
        if (length(L) < 2) next
        val <- sapply(L, function(l) rowMeans(complete[, lv == l, drop = FALSE]))
        val <- matrix(val, nrow = nrow(complete))
        for (a in 1:(length(L) - 1)) for (b in (a + 1):length(L)) {
            dd <- val[, a] - val[, b]
            row <- ef[ef$study == st & ef$measure == m & ef$factor == k &
                      ef$level_a == L[a] & ef$level_b == L[b], ]
            what <- sprintf("%s %s %s=%s - %s", st, m, k, L[a], L[b])
            if (nrow(row) != 1) {
                wrong <<- c(wrong, sprintf("%s: %d rows in effects.csv", what, nrow(row)))
                next
            }
            seen_effects <<- seen_effects + 1
            same(paste(what, "n"), row$n, length(dd))
            same(paste(what, "mean_diff"), row$mean_diff, mean(dd))
            same(paste(what, "sd_diff"), row$sd_diff, if (length(dd) > 1) sd(dd) else NA)
            b2 <- ci(dd)
            same(paste(what, "ci_low"), row$ci_low, b2[1])
            same(paste(what, "ci_high"), row$ci_high, b2[2])
            same(paste(what, "dz"), row$dz,
                 dz_of(dd))
        }
    }
    # each pair of the study's conditions: A - B over participants with both
    for (a in 1:(J - 1)) for (b in (a + 1):J) {
        dd <- pm[, a] - pm[, b]
        dd <- dd[!is.na(dd)]
        if (!length(dd)) next
        row <- pd[pd$study == st & pd$measure == m & pd$condition_a == cm[a] &
                  pd$condition_b == cm[b], ]
        what <- sprintf("%s %s %s - %s", st, m, cm[a], cm[b])
        if (nrow(row) != 1) {
            wrong <<- c(wrong, sprintf("%s: %d rows in paired.csv", what, nrow(row)))
            next
        }
        seen_pairs <<- seen_pairs + 1
        fa <- d[d$condition == cm[a], ][1, ]
        fb <- d[d$condition == cm[b], ][1, ]
        f <- c("q", "room", "cell", "cues", "minimap")
        df <- f[!mapply(function(k) identical(fa[[k]], fb[[k]]), f)]
        want <- if (length(df)) paste(df, collapse = " ") else NA
        checked <<- checked + 1
        if (!identical(row$differ, want))
            wrong <<- c(wrong, sprintf("%s differ: report %s, R %s", what, row$differ, want))
        same(paste(what, "n"), row$n, length(dd))
        same(paste(what, "mean_diff"), row$mean_diff, mean(dd))
        same(paste(what, "sd_diff"), row$sd_diff, if (length(dd) > 1) sd(dd) else NA)
        b2 <- ci(dd)
        same(paste(what, "ci_low"), row$ci_low, b2[1])
        same(paste(what, "ci_high"), row$ci_high, b2[2])
        dz <- dz_of(dd)
        same(paste(what, "dz"), row$dz, dz)
    }
}
for (st in unique(inc$study)) {
    d <- inc[inc$study == st, ]
    conds <- ps$condition[ps$study == st & ps$measure == "steps"]
    conds <- unique(c(conds, ps$condition[ps$study == st]))
    for (m in measures) {
        v <- d[!is.na(d[[m]]), ]
        if (!nrow(v)) next
        # the participants' means: participant x condition
        pm <- tapply(v[[m]], list(v$participant, v$condition), mean)
        nt <- tapply(v[[m]], list(v$participant, v$condition), length)
        cm <- conds[conds %in% colnames(pm)]
        if (length(setdiff(colnames(pm), cm)))
            wrong <- c(wrong, sprintf("%s %s: conditions %s not in participants_stats.csv", st, m,
                                      paste(setdiff(colnames(pm), cm), collapse = " ")))
        pm <- pm[, cm, drop = FALSE]
        nt <- nt[, cm, drop = FALSE]
        J <- length(cm)
        complete <- pm[rowSums(is.na(pm)) == 0, , drop = FALSE]
        norm <- complete - rowMeans(complete) + mean(complete)
        for (j in seq_along(cm)) {
            x <- pm[!is.na(pm[, j]), j]
            row <- ps[ps$study == st & ps$condition == cm[j] & ps$measure == m, ]
            what <- sprintf("%s/%s %s", st, cm[j], m)
            if (nrow(row) != 1) {
                wrong <- c(wrong, sprintf("%s: %d rows in participants_stats.csv", what, nrow(row)))
                next
            }
            seen <- seen + 1
            same(paste(what, "participants"), row$participants, length(x))
            same(paste(what, "trials"), row$trials, sum(nt[, j], na.rm = TRUE))
            same(paste(what, "mean"), row$mean, mean(x))
            same(paste(what, "sd"), row$sd, if (length(x) > 1) sd(x) else NA)
            b <- ci(x)
            same(paste(what, "ci_low"), row$ci_low, b[1])
            same(paste(what, "ci_high"), row$ci_high, b[2])
            same(paste(what, "conditions"), row$conditions, J)
            same(paste(what, "n_within"), row$n_within, if (J >= 2) nrow(complete) else 0)
            w <- if (J >= 2 && nrow(complete) >= 1) norm[, j] else numeric(0)
            same(paste(what, "mean_within"), row$mean_within, if (length(w)) mean(w) else NA)
            wc <- if (length(w)) ci(w, sqrt(J / (J - 1))) else c(NA, NA)
            same(paste(what, "ci_within_low"), row$ci_within_low, wc[1])
            same(paste(what, "ci_within_high"), row$ci_within_high, wc[2])
        }
        if (J < 2) next
        effects_and_pairs(st, m, cm, pm, complete, d, length(conds) <= 32)
    }
}
# the questionnaires' scores (scores.csv's complete scores of the presets,
# a `before` placement's measure with "_before"): per study, measure and
# condition (or "study") the participants' means, as for the trials; the
# within-subjects interval over the study's conditions (not "study")
sc <- read.csv(file.path(dir, "scores.csv"), stringsAsFactors = FALSE, na.strings = "",
               colClasses = c(participant = "character", study = "character",
                              condition = "character", instrument = "character",
                              subscale = "character", placement = "character",
                              excluded = "character"))
sc$study[is.na(sc$study)] <- ""
scored <- list(ssq = c("total", "nausea", "oculomotor", "disorientation"), tlx = "raw")
is_score <- mapply(function(i, s) !is.null(scored[[i]]) && s %in% scored[[i]],
                   sc$instrument, sc$subscale)
# the scores of a duplicate or restarted run (`excluded`) left out, as
# the trials are, unless --include-restarted
q <- sc[sc$complete == 1 & !is.na(sc$score) & is_score &
        !(sc$study == "" & sc$condition == "none") &
        (is.na(sc$excluded) | sc$excluded %in% counted), ]
q$measure <- paste0(q$instrument, "_", q$subscale, ifelse(q$placement == "before", "_before", ""))
for (st in unique(q$study)) for (m in unique(q$measure[q$study == st])) {
    d <- q[q$study == st & q$measure == m, ]
    pm <- tapply(d$score, list(d$participant, d$condition), mean)
    nt <- tapply(d$score, list(d$participant, d$condition), length)
    # the conditions in the report's order (participants_stats.csv's rows)
    order_c <- unique(ps$condition[ps$study == st])
    cm <- order_c[order_c %in% setdiff(colnames(pm), "study")]
    J <- length(cm)
    cc <- pm[, cm, drop = FALSE]
    complete <- cc[rowSums(is.na(cc)) == 0, , drop = FALSE]
    norm <- if (J >= 2 && nrow(complete)) complete - rowMeans(complete) + mean(complete) else NULL
    for (cn in colnames(pm)) {
        whole <- cn == "study"
        x <- pm[!is.na(pm[, cn]), cn]
        row <- ps[ps$study == st & ps$condition == cn & ps$measure == m, ]
        what <- sprintf("%s/%s %s", st, cn, m)
        if (nrow(row) != 1) {
            wrong <- c(wrong, sprintf("%s: %d rows in participants_stats.csv", what, nrow(row)))
            next
        }
        seen <- seen + 1
        same(paste(what, "participants"), row$participants, length(x))
        same(paste(what, "trials"), row$trials, sum(nt[, cn], na.rm = TRUE))
        same(paste(what, "mean"), row$mean, mean(x))
        same(paste(what, "sd"), row$sd, if (length(x) > 1) sd(x) else NA)
        b <- ci(x)
        same(paste(what, "ci_low"), row$ci_low, b[1])
        same(paste(what, "ci_high"), row$ci_high, b[2])
        same(paste(what, "conditions"), row$conditions, if (whole) 0 else J)
        w <- if (!whole && !is.null(norm)) norm[, cn] else numeric(0)
        same(paste(what, "n_within"), row$n_within, length(w))
        same(paste(what, "mean_within"), row$mean_within, if (length(w)) mean(w) else NA)
        wc <- if (length(w)) ci(w, sqrt(J / (J - 1))) else c(NA, NA)
        same(paste(what, "ci_within_low"), row$ci_within_low, wc[1])
        same(paste(what, "ci_within_high"), row$ci_within_high, wc[2])
    }
    # the paired differences and main effects of the conditions (not
    # `study`), their factors those of their first included trials
    if (J >= 2 && J <= 32)
        effects_and_pairs(st, m, cm, cc, complete, inc[inc$study == st, ], TRUE)
}
if (seen_effects != nrow(ef))
    wrong <- c(wrong, sprintf("effects.csv has %d rows, R expects %d", nrow(ef), seen_effects))
if (seen != nrow(ps))
    wrong <- c(wrong, sprintf("participants_stats.csv has %d rows, R expects %d", nrow(ps), seen))
if (seen_pairs != nrow(pd))
    wrong <- c(wrong, sprintf("paired.csv has %d rows, R expects %d", nrow(pd), seen_pairs))
if (length(wrong)) {
    cat("R referee: disagrees:\n", paste0("  ", wrong, "\n"), sep = "")
    quit(status = 1)
}
cat(sprintf("R referee: %d figures agree (%d rows, %d pairs, %d effects; tolerance 1e-9)\n",
            checked, seen, seen_pairs, seen_effects))
