#!/usr/bin/python3
"""check_ptx.py must flag each of the three ways host-only tables show up in
PTX (the fragments are nvcc 13's output for Halton and PMJ02 kernels before
their tables had device copies) and pass clean code.
Usage: check_ptx_selftest.py PATH/TO/check_ptx.py"""
import os
import subprocess
import sys
import tempfile

HEADER = ".version 9.0\n.target sm_75\n.address_size 64\n"
CASES = {
    "trap": (""".visible .entry _Z6haltonN7stratum6HaltonEjPd(
	.param .u64 _Z6haltonN7stratum6HaltonEjPd_param_0
)
{
	trap;
}
""", "trap instruction"),
    "literal address": (""".visible .entry _Z7halton2N7stratum6HaltonEPd(
	.param .u64 _Z7halton2N7stratum6HaltonEPd_param_1
)
{
	.reg .b64 	%rd<20>;
	mov.u64 	%rd16, 4;
	ld.u32 	%rd2, [%rd16];
	ret;
}
""", "literal address 4"),
    "endless loop": (""".visible .entry _Z10pmj_kernelmjPm(
	.param .u64 _Z10pmj_kernelmjPm_param_0
)
{
	@%p1 bra 	$L__BB1_2;
	bra.uni 	$L__BB1_1;
$L__BB1_2:
	ret;
$L__BB1_1:
	bra.uni 	$L__BB1_1;
}
""", "branch to itself"),
    "clean": (""".extern .func  (.param .b32 func_retval0) vprintf
(
	.param .b64 vprintf_param_0
)
;
.visible .entry _Z5cleanPm(
	.param .u64 _Z5cleanPm_param_0
)
{
	.reg .b64 	%rd<4>;
	ld.param.u64 	%rd1, [_Z5cleanPm_param_0];
	mov.u64 	%rd2, table;
	ld.global.u64 	%rd3, [%rd2];
	st.global.u64 	[%rd1], %rd3;
$L__BB0_1:
	add.s64 	%rd3, %rd3, 1;
	bra.uni 	$L__BB0_1;
}
""", None),
}


def main(checker):
    failures = 0
    with tempfile.TemporaryDirectory() as folder:
        for name, (body, expected) in CASES.items():
            path = os.path.join(folder, name.replace(" ", "_") + ".ptx")
            with open(path, "w", encoding="utf-8") as stream:
                stream.write(HEADER + body)
            result = subprocess.run([sys.executable, checker, path], capture_output=True, text=True)
            ok = (result.returncode == 0) if expected is None else (result.returncode == 1 and expected in result.stdout)
            print(f"{name}: exit {result.returncode}, {'as expected' if ok else 'WRONG'}\n{result.stdout}")
            failures += not ok
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
