/* SPDX-License-Identifier: BSD-3-Clause */
#include "mex_results.h"

static const char* const kResultFields[] = {"scenario",      "scenario_code", "aligned",
                                            "certificate",   "contact_count", "contacts"};
/* The contacts' and crossings' fields, and the lines that set them below, are written from the
 * field lists (scripts/projections/mex_results.py; `cmake --build build --target projections`). */
static const char* const kContactFields[] = {
    /* BEGIN GENERATED Contact names */
    "type", "base", "depth", "depth_error_bound", "p_WCj", "p_WCj_error_bound", "p_WCi",
    "p_WCi_error_bound", "normal_W", "crossings", "certificate"
    /* END GENERATED Contact names */
};
static const char* const kCrossingFields[] = {
    /* BEGIN GENERATED RimCrossing names */
    "angle", "angle_error_bound", "point", "point_error_bound", "multiplicity"
    /* END GENERATED RimCrossing names */
};
static const char* const kCertificateFields[] = {"level", "level_code", "reason", "reason_code"};

#define COUNT_OF(a) ((int)(sizeof(a) / sizeof((a)[0])))

static mxArray* row3(const double v[3]) {
  mxArray* out = mxCreateDoubleMatrix(1, 3, mxREAL);
  double* p = mxGetPr(out);
  p[0] = v[0];
  p[1] = v[1];
  p[2] = v[2];
  return out;
}

static mxArray* certificate(const cj_certificate* c) {
  mxArray* out = mxCreateStructMatrix(1, 1, COUNT_OF(kCertificateFields), (const char**)kCertificateFields);
  mxSetFieldByNumber(out, 0, 0, mxCreateString(cj_certainty_string(c->level)));
  mxSetFieldByNumber(out, 0, 1, mxCreateDoubleScalar(c->level));
  mxSetFieldByNumber(out, 0, 2, mxCreateString(c->reason_text));
  mxSetFieldByNumber(out, 0, 3, mxCreateDoubleScalar(c->reason));
  return out;
}

static mxArray* crossings(const cj_contact* c) {
  int k;
  mxArray* out = mxCreateStructMatrix((mwSize)c->crossing_count, 1, COUNT_OF(kCrossingFields),
                                      (const char**)kCrossingFields);
  for (k = 0; k < c->crossing_count; ++k) {
    const cj_crossing* x = &c->crossings[k];
    /* BEGIN GENERATED RimCrossing values */
    mxSetFieldByNumber(out, k, 0, mxCreateDoubleScalar(x->angle));
    mxSetFieldByNumber(out, k, 1, mxCreateDoubleScalar(x->angle_error_bound));
    mxSetFieldByNumber(out, k, 2, row3(x->point));
    mxSetFieldByNumber(out, k, 3, mxCreateDoubleScalar(x->point_error_bound));
    mxSetFieldByNumber(out, k, 4, mxCreateDoubleScalar(x->multiplicity));
    /* END GENERATED RimCrossing values */
  }
  return out;
}

static mxArray* contacts(int contact_count, const cj_contact* all) {
  int k;
  mxArray* out = mxCreateStructMatrix((mwSize)contact_count, 1, COUNT_OF(kContactFields),
                                      (const char**)kContactFields);
  for (k = 0; k < contact_count; ++k) {
    const cj_contact* c = &all[k];
    /* BEGIN GENERATED Contact values */
    mxSetFieldByNumber(out, k, 0, mxCreateString(cj_contact_type_string(c->type)));
    mxSetFieldByNumber(out, k, 1, mxCreateString(cj_base_string(c->base)));
    mxSetFieldByNumber(out, k, 2, mxCreateDoubleScalar(c->depth));
    mxSetFieldByNumber(out, k, 3, mxCreateDoubleScalar(c->depth_error_bound));
    mxSetFieldByNumber(out, k, 4, row3(c->p_WCj));
    mxSetFieldByNumber(out, k, 5, mxCreateDoubleScalar(c->p_WCj_error_bound));
    mxSetFieldByNumber(out, k, 6, row3(c->p_WCi));
    mxSetFieldByNumber(out, k, 7, mxCreateDoubleScalar(c->p_WCi_error_bound));
    mxSetFieldByNumber(out, k, 8, row3(c->normal_W));
    mxSetFieldByNumber(out, k, 9, crossings(c));
    mxSetFieldByNumber(out, k, 10, certificate(&c->certificate));
    /* END GENERATED Contact values */
  }
  return out;
}

mxArray* mex_create_results(size_t count) {
  return mxCreateStructMatrix((mwSize)count, 1, COUNT_OF(kResultFields), (const char**)kResultFields);
}

/* The fields every answer has; `scenario` is the scenario's key. */
static void set_fields(mxArray* results, size_t index, const char* scenario, int32_t scenario_code,
                       int32_t aligned, const cj_certificate* c, int32_t contact_count,
                       const cj_contact* all) {
  const mwIndex i = (mwIndex)index;
  mxSetFieldByNumber(results, i, 0, mxCreateString(scenario));
  mxSetFieldByNumber(results, i, 1, mxCreateDoubleScalar(scenario_code));
  mxSetFieldByNumber(results, i, 2, mxCreateLogicalScalar(aligned != 0));
  mxSetFieldByNumber(results, i, 3, certificate(c));
  mxSetFieldByNumber(results, i, 4, mxCreateDoubleScalar(contact_count));
  mxSetFieldByNumber(results, i, 5, contacts(contact_count, all));
}

void mex_set_result(mxArray* results, size_t index, const cj_result* r) {
  set_fields(results, index, cj_scenario_string(r->scenario), r->scenario, r->aligned, &r->certificate,
             r->contact_count, r->contacts);
}

void mex_set_pin_in_hole_result(mxArray* results, size_t index, const cj_pin_in_hole_result* r) {
  set_fields(results, index, cj_pin_in_hole_scenario_string(r->scenario), r->scenario, r->aligned,
             &r->certificate, r->contact_count, r->contacts);
}
