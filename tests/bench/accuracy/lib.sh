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
