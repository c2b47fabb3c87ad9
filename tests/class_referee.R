# class_referee.R - R (base only) as the referee of `holonomy report
# --class` (docs/teaching.md "A class's results"; tests/cli_class.sh runs
# it): from the pupils' answer files alone (PUPILS/NAME.csv, or
# PUPILS/NAME/answers.csv) and the keys the report names (class_items.csv's
# right_answer; test_quiz and test_lesson check the keys against the
# model; a lesson's prediction is judged in its attempt's tiling from the
# pupil folder's summary.csv, else {4,5}) it recomputes
# each item's answered, right and rate, each pupil's pre and post score
# (the share of the four items right, an item's last answer counting), the
# gain's mean, SD and 95 % CI (qt), d_z, g_av = J * gain / mean(SD pre, SD
# post), J = 1 - 3 / (4 (n - 1) - 1), and every wrong answer's count and
# share. Every figure must agree to 1e-9 and every row be there.
# Usage: Rscript class_referee.R PUPILS OUT. Exit 0 ("R referee: N figures
# agree"), else 1 naming each disagreement.
args <- commandArgs(trailingOnly = TRUE)
pupils_dir <- args[1]
out <- args[2]
tol <- 1e-9
checked <- 0
wrong <- character(0)
same <- function(what, got, want) {
    ok <- (is.na(got) && is.na(want)) || (!is.na(got) && !is.na(want) && abs(got - want) <= tol)
    checked <<- checked + 1
    if (!ok) wrong <<- c(wrong, sprintf("%s: report %s, R %s", what, format(got, digits = 17),
                                        format(want, digits = 17)))
}
rd <- function(path) read.csv(path, stringsAsFactors = FALSE, na.strings = NULL,
                              colClasses = "character")
names <- sort(list.files(pupils_dir), method = "radix")
rows <- NULL
for (n in names) {
    p <- file.path(pupils_dir, n)
    q <- NULL
    if (dir.exists(p)) {
        f <- file.path(p, "answers.csv")
        name <- n
        sf <- file.path(p, "summary.csv")
        if (file.exists(sf)) q <- rd(sf)
    } else if (grepl("\\.csv$", n)) {
        f <- p
        name <- sub("\\.csv$", "", n)
    } else next
    if (!file.exists(f)) next
    a <- rd(f)[, c("session", "participant", "attempt", "questionnaire", "when", "item",
                   "kind", "value", "time")] # the timestamps' columns or not
    a$pupil <- ifelse(a$participant == "", name, a$participant)
    # a lesson's tiling: its attempt's in summary.csv, else {4,5}
    a$q <- "5"
    if (!is.null(q)) {
        m <- match(paste(a$session, a$attempt), paste(q$session, q$attempt))
        a$q[!is.na(m)] <- sub("^4,", "", q$tiling[m[!is.na(m)]])
    }
    rows <- rbind(rows, a)
}
lesson <- rows$questionnaire == "predict" & grepl("^lesson[1-6]$", rows$item)
rows$concept <- ifelse(lesson, rows$item, sub("_q[4-8]$", "", rows$item))
rows$item[lesson] <- paste0(rows$item[lesson], "_q", rows$q[lesson])
rows <- rows[rows$questionnaire %in% c("pretest", "posttest") | lesson, ]
items <- rd(file.path(out, "class_items.csv"))
rows$key <- paste(rows$questionnaire, rows$item)
keys <- setNames(items$right_answer, paste(items$phase, items$item))
rows <- rows[rows$key %in% names(keys), ]
rows$right <- rows$value == keys[rows$key]
# an item's last answer: the last row of a pupil, phase and concept
last <- rows[!duplicated(paste(rows$pupil, rows$questionnaire, rows$concept), fromLast = TRUE), ]
for (i in seq_len(nrow(items))) {
    s <- last[last$questionnaire == items$phase[i] & last$item == items$item[i], ]
    what <- paste(items$phase[i], items$item[i])
    same(paste(what, "answered"), as.numeric(items$answered[i]), nrow(s))
    same(paste(what, "right"), as.numeric(items$right[i]), sum(s$right))
    same(paste(what, "rate"), as.numeric(items$rate[i]), mean(s$right))
}
score <- function(p, ph) {
    s <- last[last$pupil == p & last$questionnaire == ph, ]
    if (nrow(s) == 0) NA else sum(s$right) / 4
}
pu <- rd(file.path(out, "class_pupils.csv"))
ids <- unique(last$pupil)
if (!setequal(ids, pu$pupil)) wrong <- c(wrong, "class_pupils.csv's pupils differ")
num <- function(x) ifelse(x == "", NA, as.numeric(x))
pre <- c(); post <- c()
for (i in seq_len(nrow(pu))) {
    a <- score(pu$pupil[i], "pretest"); b <- score(pu$pupil[i], "posttest")
    same(paste(pu$pupil[i], "pre"), num(pu$pre[i]), a)
    same(paste(pu$pupil[i], "post"), num(pu$post[i]), b)
    same(paste(pu$pupil[i], "gain"), num(pu$gain[i]), b - a)
    if (!is.na(a) && !is.na(b)) { pre <- c(pre, a); post <- c(post, b) }
}
g <- rd(file.path(out, "class_gain.csv"))
n <- length(pre)
d <- post - pre
h <- qt(0.975, n - 1) * sd(d) / sqrt(n)
J <- 1 - 3 / (4 * (n - 1) - 1)
want <- c(pupils = n, pre_mean = mean(pre), pre_sd = sd(pre), post_mean = mean(post),
          post_sd = sd(post), gain_mean = mean(d), gain_sd = sd(d), gain_ci_low = mean(d) - h,
          gain_ci_high = mean(d) + h, d_z = mean(d) / sd(d),
          g_av = J * mean(d) / ((sd(pre) + sd(post)) / 2))
for (k in names(want)) same(paste("gain", k), num(g[[k]][1]), want[[k]])
# the wrong answers: count and share of the item's answers
wr <- rd(file.path(out, "class_wrong.csv"))
bad <- last[!last$right, ]
tab <- aggregate(list(count = rep(1, nrow(bad))),
                 list(phase = bad$questionnaire, item = bad$item, answer = bad$value), sum)
if (nrow(tab) != nrow(wr)) wrong <- c(wrong, sprintf("class_wrong.csv: %d rows, R %d",
                                                     nrow(wr), nrow(tab)))
for (i in seq_len(nrow(tab))) {
    j <- which(wr$phase == tab$phase[i] & wr$item == tab$item[i] & wr$answer == tab$answer[i])
    what <- paste("wrong", tab$phase[i], tab$item[i], tab$answer[i])
    if (length(j) != 1) { wrong <- c(wrong, paste(what, "missing")); next }
    answered <- sum(last$questionnaire == tab$phase[i] & last$item == tab$item[i])
    same(paste(what, "count"), as.numeric(wr$count[j]), tab$count[i])
    same(paste(what, "share"), as.numeric(wr$share[j]), tab$count[i] / answered)
}
if (length(wrong)) {
    cat(wrong, sep = "\n")
    quit(status = 1)
}
cat(sprintf("R referee: %d figures agree\n", checked))
