% SPDX-License-Identifier: BSD-3-Clause
% The C API's status of a MEX gateway's error (README.md), for an equivalence line.
function s = equivalence_status(err)
  if strcmp(err.identifier, 'clearjoint:invalidInput')
    s = 1;  % CJ_INVALID_INPUT
  else
    s = 3;  % CJ_INTERNAL_ERROR
  end
end
