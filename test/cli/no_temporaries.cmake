# SPDX-License-Identifier: GPL-3.0-or-later
# expect_no_temporaries(DIR WHAT): no output's temporary (.NAME.tmp.PID) is
# left in DIR; WHAT names the run in the error.
function(expect_no_temporaries dir what)
  file(GLOB temporaries ${dir}/*tmp*)
  if(temporaries)
    message(FATAL_ERROR "${what}: temporary files left: ${temporaries}")
  endif()
endfunction()
