# Reference values for tests/report/test_paired_statistics.cpp, computed by R (not by
# frontier-sweep): wilcox.test's two-sided signed-rank p-values and statistic V, psignrank,
# and p.adjust(method = "holm"). Run: Rscript tests/report/reference/wilcoxon_reference.R
# Its output is pasted into the test as constants; R is not needed to run the tests.
cases <- list(
  # R's own example (?wilcox.test, Hollander & Wolfe p. 29): exact, no ties.
  depression = c(1.83, 0.50, 1.62, 2.48, 1.68, 1.88, 1.55, 3.06, 1.30) -
               c(0.878, 0.647, 0.598, 2.05, 1.06, 1.29, 1.06, 3.14, 1.29),
  single = c(2.5),
  all_negative = -(1:10),
  ties = c(1, 1, 2, -3, 4, 4, 5),
  zeros = c(0, 1.5, -2, 3, 0, 4.5, 6),
  ties_and_zeros = c(0, -1, -1, 2, -2, -3, 0, -4, 5, -6, -6),
  n49 = sin(1:49) * 10 + 0.7,
  n50 = sin(1:50) * 10 + 0.7,
  n80_ties = round(cos(1:80) * 4) + 0.5
)
fmt <- function(x) ifelse(is.na(x), "NA", sprintf("%.17g", x))
for (name in names(cases)) {
  x <- cases[[name]]
  r <- suppressWarnings(wilcox.test(x, mu = 0, alternative = "two.sided"))
  cat(sprintf("%s: V = %s, p = %s, method = %s\n", name, fmt(unname(r$statistic)), fmt(r$p.value), r$method))
}
for (q in list(c(0, 5), c(7, 5), c(15, 10), c(27, 10), c(100, 20), c(600, 49))) {
  cat(sprintf("psignrank(%d, %d) = %s\n", q[1], q[2], fmt(psignrank(q[1], q[2]))))
}
p <- c(0.01, 0.04, NA, 0.03, 0.005, 0.5)
cat("holm(", paste(p, collapse = ", "), ") =", paste(fmt(p.adjust(p, "holm")), collapse = ", "), "\n")
cat("qnorm(0.975) =", fmt(qnorm(0.975)), "\n")
cat("R:", R.version.string, "\n")
