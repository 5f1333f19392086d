# The built program and its C layer on the platform: no executable stack (readelf), and the
# C layer's branch for macOS and the BSDs (getentropy, /dev/fd) compiles and works, forced
# on Linux with -DKINETOSTAT_FORCE_PORTABLE.

# --- no executable stack: readelf -lW shows the GNU_STACK segment's flags, RW (RWE would
# mean a trampoline of an internal procedure passed as an argument, tools/test's
# -Wtrampolines build refuses those)
# stack_flags FILE: the flags of FILE's GNU_STACK segment ("RW", "RWE"), "none" without one.
stack_flags() {
  readelf -lW "$1" 2>/dev/null | awk '$1 == "GNU_STACK" { f = ""; for (i = 7; i < NF; i++) f = f $i; print f; found = 1 }
    END { if (!found) print "none" }'
}
if ! command -v readelf >/dev/null 2>&1; then
  echo "note: platform-stack skipped (no readelf: apt-get install binutils)"
else
  pf_flags="$(stack_flags "$KINETOSTAT")"
  [ "$pf_flags" = "RW" ] && pass || fail platform-stack-not-executable \
    "readelf -lW $KINETOSTAT: GNU_STACK flags '$pf_flags', expected 'RW'"
  # the check can fail: a program passing an internal procedure has an executable stack
  if command -v gfortran >/dev/null 2>&1; then
    cat >"$cli_tmp/tramp.f90" <<'EOF'
program tramp
  implicit none
  integer :: n
  n = 2
  call apply(add_n)
contains
  subroutine add_n(k)
    integer, intent(in) :: k
    print *, k + n
  end subroutine add_n
  subroutine apply(f)
    interface
      subroutine f(k)
        integer, intent(in) :: k
      end subroutine f
    end interface
    call f(1)
  end subroutine apply
end program tramp
EOF
    if gfortran "$cli_tmp/tramp.f90" -o "$cli_tmp/tramp" 2>"$cli_tmp/tramp.err"; then
      pf_flags="$(stack_flags "$cli_tmp/tramp")"
      [ "$pf_flags" = "RWE" ] && pass || fail platform-stack-check-can-fail \
        "a program with a trampoline: GNU_STACK flags '$pf_flags', expected 'RWE' (the checker sees nothing?)"
    else
      fail platform-stack-check-can-fail "gfortran: $(head -3 "$cli_tmp/tramp.err")"
    fi
  fi
fi

# --- the C layer: both branches compile with every warning an error; the portable one
# (getentropy, the descriptor directory /dev/fd) is run through its output plans
pf_c="$(command -v gcc || command -v cc)"
if [ -z "$pf_c" ]; then
  echo "note: platform-c skipped (no C compiler)"
else
  for pf_define in "" -DKINETOSTAT_FORCE_PORTABLE; do
    if "$pf_c" -std=c11 -Wall -Wextra -Werror $pf_define -c src/core/kinetostat_posix.c -o "$cli_tmp/posix.o" \
      2>"$cli_tmp/posix.err"; then pass
    else fail "platform-c-compiles${pf_define:+-portable}" "$(head -5 "$cli_tmp/posix.err")"; fi
  done
  cat >"$cli_tmp/plan.c" <<'EOF'
#include <stdio.h>
#include <string.h>
#include <unistd.h>
int kinetostat_output_plan(const char *path, char *final, int cap, int *fd);
int kinetostat_temp_beside(const char *final, char *name, int cap);
void kinetostat_temp_remove(const char *name);
/* ARGS: paths; prints "PLAN FD" for each, then two temporaries' names beside the last. */
int main(int argc, char **argv) {
  char final[4096], a[4096], b[4096];
  int fd, i;
  for (i = 1; i < argc; i++) {
    int plan = kinetostat_output_plan(argv[i], final, (int) sizeof final, &fd);
    fprintf(stderr, "%d %d\n", plan, fd);
  }
  fd = kinetostat_temp_beside(argv[argc - 1], a, (int) sizeof a);
  if (fd < 0) return 1;
  close(fd);
  fd = kinetostat_temp_beside(argv[argc - 1], b, (int) sizeof b);
  if (fd < 0) return 1;
  close(fd);
  fprintf(stderr, "%s\n%s\n", a, b);
  kinetostat_temp_remove(a);
  kinetostat_temp_remove(b);
  return 0;
}
EOF
  # both branches give the same plans on Linux
  for pf_define in "" -DKINETOSTAT_FORCE_PORTABLE; do
    if "$pf_c" -std=c11 $pf_define src/core/kinetostat_posix.c "$cli_tmp/plan.c" -o "$cli_tmp/plan" \
      2>"$cli_tmp/plan.err"; then
      # /dev/stdout and /dev/fd/1: this process' descriptor 1 (plan 3); a new file: replaced
      # (plan 1); /dev/null: written directly (plan 2)
      "$cli_tmp/plan" /dev/stdout /dev/fd/1 /dev/null "$cli_tmp/new.out" >"$cli_tmp/plan.stdout" 2>"$cli_tmp/plan.out"
      pf_rc=$?
      pf_want="$(printf '3 1\n3 1\n2 -1\n1 -1')"
      pf_names="$(sed -n '5,6p' "$cli_tmp/plan.out")"
      if [ "$pf_rc" -eq 0 ] && [ "$(head -4 "$cli_tmp/plan.out")" = "$pf_want" ] \
        && [ "$(echo "$pf_names" | grep -c "^$cli_tmp/new.out.tmp.[A-Za-z0-9]\{12\}$")" -eq 2 ] \
        && [ "$(echo "$pf_names" | sort -u | wc -l)" -eq 2 ] && ! ls "$cli_tmp"/new.out.tmp.* >/dev/null 2>&1; then pass
      else fail "platform-c-plans${pf_define:+-portable}" "exit $pf_rc; plans and names:
$(cat "$cli_tmp/plan.out")
expected the plans:
$pf_want"; fi
    else
      fail "platform-c-links${pf_define:+-portable}" "$(head -5 "$cli_tmp/plan.err")"
    fi
  done
fi
