# tests/bench/accuracy/lib.sh: the image error used by tests/bench/accuracy.sh
# (sourced; checked by selftest.sh).
#
# acc_error REF IMG: prints "RMS MAX", the root mean square and the largest
# absolute difference between IMG and REF over every pixel and channel, in
# the files' own values (linear float for EXR), as computed by OpenImageIO's
# idiff. Prints nothing and fails when idiff cannot compare the two.
acc_error() {
	idiff -v -fail 1e30 -warn 1e30 "$1" "$2" 2> /dev/null | awk '
		/RMS error =/ { rms = $4 }
		/Max error +=/ { max = $4 }
		END { if (rms == "" || max == "") exit 1; print rms, max }'
}

# acc_compare MODE: reads "renderer time rms" lines (renderer l for lucent,
# p for POV-Ray) and prints "median lowest highest levels only_l only_p":
# POV-Ray's time over lucent's to reach the same RMS error, at every error
# level one of them measured, over the levels both reach; then the number
# of levels only lucent and only POV-Ray reach. A renderer's time to reach
# error E:
#   step  the fastest of its settings whose error is at most E;
#   line  on its curve: its fastest settings (each with less error than
#         every faster one) joined by straight lines on the log-log plot;
#         above the fastest setting's error, that setting's time (as step).
# Times under 1 ms count as 1 ms.
acc_compare() {
	sort -k1,1 -k2,2g | awk -v mode="$1" '
		{ t = ($2 < 0.001 ? 0.001 : $2) + 0; e = $3 + 0; lev[e] = 1
		  if ($1 == "l") { if (!nl || e < le[nl]) { nl++; lt[nl] = t; le[nl] = e } }
		  else { if (!np || e < pe[np]) { np++; pt[np] = t; pe[np] = e } } }
		# The time of the front (n points, t[], e[]) at error E, -1 if it
		# does not get there.
		function reach(n, t, e, E,   i, f) {
			if (n == 0 || E < e[n]) return -1
			if (E >= e[1]) return t[1]
			for (i = 1; i < n && E < e[i + 1]; i++) ;
			if (mode == "step" || E == e[i + 1]) return t[i + 1]
			f = log(e[i] / E) / log(e[i] / e[i + 1])
			return t[i] * exp(f * log(t[i + 1] / t[i])) }
		END {
			k = 0; ol = 0; op = 0
			for (E in lev) {
				a = reach(nl, lt, le, E + 0); b = reach(np, pt, pe, E + 0)
				if (a > 0 && b > 0) r[++k] = b / a
				else if (a > 0) ol++
				else if (b > 0) op++ }
			if (k == 0) { print "- - - 0", ol, op; exit }
			for (i = 2; i <= k; i++) { v = r[i]; for (j = i - 1; j >= 1 && r[j] > v; j--) r[j + 1] = r[j]; r[j + 1] = v }
			med = k % 2 ? r[(k + 1) / 2] : (r[k / 2] + r[k / 2 + 1]) / 2
			printf "%.2f %.2f %.2f %d %d %d\n", med, r[1], r[k], k, ol, op }'
}
