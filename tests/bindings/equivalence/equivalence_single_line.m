% SPDX-License-Identifier: BSD-3-Clause
% One single-call answer of a MEX gateway as an equivalence line (README.md): the paper's joint
% (cj_detect) and the pin-in-hole joint (cj_detect_pin_in_hole) share it.
function line = equivalence_single_line(i, r)
  line = sprintf('S %d ok %d %d %d %d "%s" %d', i, r.scenario_code, r.aligned, ...
                 r.certificate.level_code, r.certificate.reason_code, r.certificate.reason, ...
                 r.contact_count);
  for k = 1:r.contact_count
    c = r.contacts(k);
    line = [line, sprintf(' | %d %d', type_code(c.type), base_code(c.base)), hex(c.depth), ...
            hex(c.p_WCj), hex(c.p_WCi), hex(c.normal_W), hex(c.depth_error_bound), ...
            hex(c.p_WCj_error_bound), hex(c.p_WCi_error_bound), sprintf(' %d', numel(c.crossings))];
    for m = 1:numel(c.crossings)
      x = c.crossings(m);
      line = [line, hex(x.angle), hex(x.angle_error_bound), hex(x.point), ...
              hex(x.point_error_bound), sprintf(' %d', x.multiplicity)];
    end
    line = [line, sprintf(' %d %d "%s"', c.certificate.level_code, c.certificate.reason_code, ...
                          c.certificate.reason)];
  end
end

function t = hex(x)
  % IEEE bits of each double, 16 upper-case hex digits after a space.
  h = upper(num2hex(x(:)));
  t = reshape([repmat(' ', rows(h), 1), h]', 1, []);
end

function code = type_code(name)
  code = find(strcmp(name, {'radial', 'axial'})) - 1;
end

function code = base_code(name)
  code = find(strcmp(name, {'a', 'b', 'mid'})) - 1;
end
