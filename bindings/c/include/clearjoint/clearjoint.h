/* SPDX-License-Identifier: BSD-3-Clause */
#ifndef CLEARJOINT_CLEARJOINT_H
#define CLEARJOINT_CLEARJOINT_H
/**
 * \file
 * The C API of clearjoint: contact detection between the journal and the bearing of a spatial
 * revolute joint with clearance (Marques et al. 2017, Section 3), and the two kernel queries it
 * is made of. C99, usable from C and C++, and from any language that can call C (the MATLAB/Octave
 * MEX gateway in bindings/matlab and the Fortran module in bindings/fortran are built on it).
 *
 * It wraps the C++ API (clearjoint/geometry/joint/detect_contacts.hpp and the headers it includes,
 * where the mathematics and the conventions are documented): the answers are the C++ answers,
 * bit for bit. No C++ type and no exception crosses it.
 *
 * Errors. Every function that can fail returns a cj_status. Those functions take a message
 * buffer (`message`, `message_capacity`): on failure the reason is written there, naming the
 * offending field and its value ("journal.axis_W = [0, 0, 0]: must not be the zero vector"),
 * always NUL-terminated and truncated to fit; on success an empty string is written. NULL with
 * capacity 0 means "no message wanted". There is no global error state: every function is
 * thread-safe as long as two threads do not write to the same result or buffer.
 *
 * Units: lengths in any one unit (metres in the paper), angles in radians. Frames: every vector is
 * in the world frame W; `p_WX` names point X measured from W's origin.
 *
 * ABI rules (what may change, and how):
 *  - The library's soname (libclearjoint_c.so.MAJOR.MINOR) changes whenever the ABI does; within
 *    one soname no function signature, struct layout or enum value changes, and CJ_ABI_VERSION
 *    stays the same.
 *  - Structs never grow. Room for later fields is reserved inside them: `reserved` members in the
 *    structs a caller fills in must be zero (cj_default_options() and zero-initialisation give
 *    that), and a call rejects a nonzero reserved field, so a program written for a later version
 *    fails loudly against an older library instead of being silently ignored; such a field is
 *    given a meaning only where zero keeps the old behaviour. `reserved` members of the structs
 *    the library fills in hold unspecified values: callers must not read them.
 *  - Enums may gain values at the end (a new scenario, a new certificate reason). Callers must
 *    handle values they do not know; the to-string functions return "unknown" for them.
 *  - New functions may be added at any version.
 *  - Every struct member that holds an enum value is an int32_t, and booleans are int32_t
 *    (0 or 1), so that the layout is the same for every C compiler and for Fortran's
 *    BIND(C) types.
 */

#include <stddef.h>
#include <stdint.h>

#if defined(_WIN32) && !defined(CJ_STATIC)
#  if defined(CJ_BUILDING_LIBRARY)
#    define CJ_API __declspec(dllexport)
#  else
#    define CJ_API __declspec(dllimport)
#  endif
#elif defined(__GNUC__)
#  define CJ_API __attribute__((visibility("default")))
#else
#  define CJ_API
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* ---- Versions --------------------------------------------------------------------------------- */

/** The layout version of the structs in this header. Raised only together with the soname. */
#define CJ_ABI_VERSION 1

/** The version of the linked library, "MAJOR.MINOR.PATCH" (a static string). */
CJ_API const char* cj_version(void);
/** CJ_ABI_VERSION of the linked library: compare it with the macro to detect a header that does
 * not match the library. */
CJ_API int cj_abi_version(void);

/* ---- Status ----------------------------------------------------------------------------------- */

typedef enum cj_status {
  CJ_OK = 0,
  /** An input is NULL, non-finite, out of its range or inconsistent; the message names it. */
  CJ_INVALID_INPUT = 1,
  /** The exact (rational) fallback could not allocate memory. */
  CJ_OUT_OF_MEMORY = 2,
  /** Anything else: a bug in clearjoint; the message says what was caught. */
  CJ_INTERNAL_ERROR = 3
} cj_status;

/** "ok", "invalid input", "out of memory", "internal error", or "unknown". */
CJ_API const char* cj_status_string(int status);

/* ---- Enums ------------------------------------------------------------------------------------ */

/* The enums below are the library's enum tables (clearjoint/geometry/model/enum_table.hpp),
 * written by scripts/projections (cmake --build build --target projections): edit the tables. */
/* BEGIN GENERATED enums */
/** The contact scenarios of the paper's Fig. 2, plus free flight and "beyond the model" (C++:
 * ContactScenario). */
typedef enum cj_scenario {
  CJ_SCENARIO_NONE = 0, /**< none */
  CJ_SCENARIO_SINGLE_RADIAL = 1, /**< (a) single radial */
  CJ_SCENARIO_SINGLE_AXIAL = 2, /**< (b) single axial */
  CJ_SCENARIO_RADIAL_AT_BOTH_BASES = 3, /**< (c) radial at both bases */
  CJ_SCENARIO_AXIAL_AT_BOTH_BASES = 4, /**< (d) axial at both bases */
  CJ_SCENARIO_RADIAL_AND_AXIAL_SAME_BASE = 5, /**< (e) radial and axial at the same base */
  CJ_SCENARIO_RADIAL_AND_AXIAL_OPPOSITE_BASES = 6, /**< (f) radial and axial at opposite bases */
  CJ_SCENARIO_TWO_RADIAL_ONE_AXIAL = 7, /**< (g) two radial, one axial */
  CJ_SCENARIO_ONE_RADIAL_TWO_AXIAL = 8, /**< (h) one radial, two axial */
  CJ_SCENARIO_ALL_FOUR = 9, /**< (i) all four */
  CJ_SCENARIO_LINE = 10, /**< (j) line */
  CJ_SCENARIO_FACE = 11, /**< (k) face */
  CJ_SCENARIO_LINE_AND_FACE = 12, /**< (l) line and face */
  CJ_SCENARIO_BEYOND_MODEL = 13 /**< beyond model */
} cj_scenario;

/** Trust in an answer, strongest first (C++: Certainty). */
typedef enum cj_certainty {
  CJ_CERTAINTY_EXACT = 0, /**< decided with exact rational arithmetic */
  CJ_CERTAINTY_CERTIFIED = 1, /**< proved in floating point with rigorous error bounds */
  CJ_CERTAINTY_UNCERTAIN = 2 /**< not proved; the certificate's reason says why */
} cj_certainty;

/** Why an answer is `uncertain`, or for an `exact` one why the floating-point tiers did not
 * decide it; CJ_REASON_NONE for certified answers (C++: CertificateReason). `reason_text` and
 * cj_reason_string() give the sentence. */
typedef enum cj_reason {
  CJ_REASON_NONE = 0,
  CJ_REASON_NOT_DECIDED = 1, /**< not decided (a default-constructed certificate) */
  CJ_REASON_CERTIFICATE_SWITCHED_OFF = 2, /**< certificate switched off */
  /** floating-point filter could not decide (tangent or parallel) */
  CJ_REASON_PLANE_FILTER_UNDECIDED = 3,
  /** floating-point filter could not decide and the exact fallback is off */
  CJ_REASON_PLANE_FILTER_UNDECIDED_EXACT_FALLBACK_OFF = 4,
  /** crossing points, depth or their error bounds not representable in double (intermediate
   * under- or overflow: input magnitudes too far apart); the topology is still decided */
  CJ_REASON_PLANE_RESULTS_NOT_REPRESENTABLE = 5,
  /** subdivision budget exhausted (roots too close: near tangency) */
  CJ_REASON_SUBDIVISION_BUDGET_EXHAUSTED = 6,
  /** more than four roots found (cannot happen for a proper rim) */
  CJ_REASON_MORE_THAN_FOUR_ROOTS = 7,
  /** interval proof failed near a multiple root (tangency) */
  CJ_REASON_INTERVAL_PROOF_FAILED_NEAR_MULTIPLE_ROOT = 8,
  CJ_REASON_COEFFICIENT_OVERFLOW = 9, /**< coefficient overflow in double precision */
  /** crossing points or their error bounds not representable in double (intermediate under- or
   * overflow: input magnitudes too far apart); the root count is still decided */
  CJ_REASON_CYLINDER_POINTS_NOT_REPRESENTABLE = 10,
  /** exact tier gave up: root isolation exceeded its budget (input magnitudes too far apart) */
  CJ_REASON_EXACT_ROOT_ISOLATION_BUDGET_EXHAUSTED = 11,
  /** exact tier gave up: polynomial coefficients too large (input magnitudes too far apart) */
  CJ_REASON_EXACT_COEFFICIENTS_TOO_LARGE = 12,
  /** exact tier gave up: an intermediate value left the double range (input magnitudes too far
   * apart) */
  CJ_REASON_EXACT_INTERMEDIATE_BEYOND_DOUBLE_RANGE = 13,
  /** a contact point, depth or error bound not representable in double (coordinates too large for
   * the joint's size); the contact's existence is still decided */
  CJ_REASON_CONTACT_NOT_REPRESENTABLE_IN_WORLD = 14,
  /** axes treated as parallel within DetectionOptions::parallel_angle_tolerance (eq. 5 relaxed;
   * decided in double precision) */
  CJ_REASON_AXES_PARALLEL_WITHIN_TOLERANCE = 15,
  /** a contact's depth lies within its error bound of the clearance: whether the joint is beyond
   * the model (scenario beyond_model) is not proved; the contacts themselves are */
  CJ_REASON_BEYOND_MODEL_UNDECIDED = 16,
  /** the pin-in-hole joint's two edge contacts have normals at right angles within their error
   * bounds: whether they bear at opposite sides of the pin (both_edges_opposite) or on one side
   * (both_edges_same_side) is not proved; the contacts themselves are */
  CJ_REASON_EDGE_SIDES_UNDECIDED = 17
} cj_reason;

/** What a contact is against (C++: ContactType). */
typedef enum cj_contact_type {
  CJ_CONTACT_RADIAL = 0, /**< against the lateral wall (eqs. 16-21; line: eqs. 6-8) */
  CJ_CONTACT_AXIAL = 1 /**< against a base (eqs. 11-15; face: eqs. 9-10) */
} cj_contact_type;

/** Where a contact is (C++: ContactBase). */
typedef enum cj_base {
  CJ_BASE_A = 0, /**< at bearing base A (eq. 3) and the journal rim facing it */
  CJ_BASE_B = 1, /**< at bearing base B (eq. 4) and the journal rim facing it */
  CJ_BASE_MID = 2 /**< at the journal's mid-length (line contact, eqs. 6-8) */
} cj_base;

/** How a circle meets a plane (C++: CirclePlaneTopology). */
typedef enum cj_circle_plane_topology {
  CJ_CIRCLE_PLANE_DISJOINT = 0, /**< no common point; side says where the circle is */
  CJ_CIRCLE_PLANE_TANGENT = 1, /**< one common point of multiplicity 2 */
  CJ_CIRCLE_PLANE_TWO_CROSSINGS = 2, /**< the circle passes through the plane */
  CJ_CIRCLE_PLANE_CIRCLE_IN_PLANE = 3 /**< every rim point lies in the plane */
} cj_circle_plane_topology;

/** How a circle meets a cylinder's lateral surface (C++: CircleCylinderTopology). */
typedef enum cj_circle_cylinder_topology {
  CJ_CIRCLE_CYLINDER_INSIDE = 0, /**< every rim point strictly inside the wall */
  CJ_CIRCLE_CYLINDER_OUTSIDE = 1, /**< every rim point strictly beyond the wall */
  CJ_CIRCLE_CYLINDER_CROSSING = 2, /**< 1 to 4 distinct common points */
  CJ_CIRCLE_CYLINDER_ON_SURFACE = 3 /**< coaxial with equal radii */
} cj_circle_cylinder_topology;

/** The contact scenarios of the pin-in-hole joint (C++: PinInHoleScenario; docs/contact-
 * detection.md, "The pin-in-hole joint"). */
typedef enum cj_pin_in_hole_scenario {
  CJ_PIN_IN_HOLE_NONE = 0, /**< none */
  CJ_PIN_IN_HOLE_ONE_EDGE = 1, /**< one hole edge against the pin */
  CJ_PIN_IN_HOLE_BOTH_EDGES_OPPOSITE = 2, /**< both hole edges, at opposite sides (tilt) */
  CJ_PIN_IN_HOLE_BOTH_EDGES_SAME_SIDE = 3, /**< both hole edges, on one side */
  CJ_PIN_IN_HOLE_LINE = 4, /**< aligned: line contact along the bore */
  CJ_PIN_IN_HOLE_ONE_STOP = 5, /**< one stop against its link face */
  CJ_PIN_IN_HOLE_BOTH_STOPS = 6, /**< both stops against their link faces */
  CJ_PIN_IN_HOLE_FACE = 7, /**< aligned: a stop flush on its link face */
  CJ_PIN_IN_HOLE_EDGES_AND_STOPS = 8, /**< edge and stop contacts together */
  CJ_PIN_IN_HOLE_LINE_AND_FACE = 9, /**< aligned: line and face together */
  CJ_PIN_IN_HOLE_BEYOND_MODEL = 10 /**< beyond model */
} cj_pin_in_hole_scenario;
/* END GENERATED enums */

/** Static strings; "unknown" for a value this version does not know. Each is the value's key in
 * the C++ library's enum table (clearjoint/geometry/model/enum_table.hpp), the one spelling that
 * `clearjoint detect` and `clearjoint intersect` write and Python's members are named by:
 * scenarios "none", "a" ... "l" (the letters of the paper's Fig. 2), "beyond_model"; "exact",
 * "certified", "uncertain"; "radial", "axial"; bases "a", "b", "mid"; "disjoint", "tangent",
 * "two_crossings", "circle_in_plane"; "inside", "outside", "crossing", "on_surface". A reason's
 * text is its sentence ("certificate switched off"; "" for CJ_REASON_NONE). */
CJ_API const char* cj_scenario_string(int scenario);
CJ_API const char* cj_certainty_string(int certainty);
CJ_API const char* cj_reason_string(int reason);
CJ_API const char* cj_contact_type_string(int type);
CJ_API const char* cj_base_string(int base);
CJ_API const char* cj_circle_plane_topology_string(int topology);
CJ_API const char* cj_circle_cylinder_topology_string(int topology);
/** A pin-in-hole scenario's key: "none", "one_edge", "both_edges_opposite",
 * "both_edges_same_side", "line", "one_stop", "both_stops", "face", "edges_and_stops",
 * "line_and_face", "beyond_model" (the enumerators' names, as `clearjoint detect` writes them). */
CJ_API const char* cj_pin_in_hole_scenario_string(int scenario);

/* ---- Inputs ----------------------------------------------------------------------------------- */

/** Bearing radius Ri and length Li, journal radius Rj and length Lj (eqs. 1-2).
 * Valid when Ri > Rj > 0, Li > Lj > 0 and each lies in [1e-150, 1e150], the range of lengths
 * accepted (C++: kSmallestAcceptedLength, kLargestAcceptedLength): outside it the certified
 * bounds are not promised, and cj_detect returns CJ_INVALID_INPUT naming the field. Any unit
 * will do: rescale a joint outside the range. */
typedef struct cj_dimensions {
  double bearing_radius;
  double bearing_length;
  double journal_radius;
  double journal_length;
} cj_dimensions;

/** Where a part is: P, the centre of its axis segment, and its axis direction a (any nonzero
 * length; only its direction counts). Finite; each coordinate of P is 0 or of magnitude in
 * [1e-150, 1e150] (see cj_dimensions). */
typedef struct cj_pose {
  double p_WP[3];
  double axis_W[3];
} cj_pose;

typedef struct cj_options {
  /** Nonzero: prove every answer. 0: plain double-precision pipeline, answers `uncertain`. */
  int32_t certify;
  /** Nonzero: decide in exact rational arithmetic where the floating-point proof fails. */
  int32_t exact_fallback;
  /** Axes within this angle (radians, in [0, pi/2)) of parallel are treated as parallel; their
   * contacts are `uncertain`. 0: parallel only when a_i x a_j = 0 exactly (eq. 5). */
  double parallel_angle_tolerance;
  /** Must be zero (see the ABI rules). */
  double reserved[4];
} cj_options;

/** certify = 1, exact_fallback = 1, parallel_angle_tolerance = 0. A NULL options pointer means
 * the same. */
CJ_API cj_options cj_default_options(void);

/* ---- Results ---------------------------------------------------------------------------------- */

/** "No error bound known" in the *_error_bound fields is +infinity (uncertain answers). */

/** A trust level and why it is not stronger. */
typedef struct cj_certificate {
  /* BEGIN GENERATED cj_certificate members (the field list of Certificate: scripts/projections) */
  int32_t level; /**< cj_certainty */
  int32_t reason; /**< cj_reason */
  const char* reason_text; /**< static string: cj_reason_string(reason) */
  /* END GENERATED cj_certificate members */
} cj_certificate;

/** A point where a journal rim meets a bearing surface. When the answer is certified or exact,
 * the true crossing angle lies within angle_error_bound of `angle` and the true point within
 * point_error_bound (Euclidean) of `point`. */
typedef struct cj_crossing {
  /* BEGIN GENERATED cj_crossing members (the field list of RimCrossing: scripts/projections) */
  double angle; /**< rim angle in [0, 2 pi), in the rim's CircleFrame (primitives.hpp) */
  double angle_error_bound;
  double point[3];
  double point_error_bound;
  int32_t multiplicity; /**< 1 crossing, 2 tangency, 3-4 higher-order contact */
  int32_t reserved;
  /* END GENERATED cj_crossing members */
} cj_crossing;

/** One contact (C++: Contact). normal_W points out of the bearing, in the direction the journal
 * penetrates; depth = |p_WCj - p_WCi| >= 0, so p_WCj - p_WCi = depth * normal_W up to rounding
 * (eqs. 22-23). The error bounds: the contact of the joint as given has its journal point within
 * p_WCj_error_bound of p_WCj (Euclidean), its bearing point within p_WCi_error_bound of p_WCi and
 * its depth within depth_error_bound of depth; certified enclosures unless the contact is
 * uncertain. */
typedef struct cj_contact {
  /* BEGIN GENERATED cj_contact members (the field list of Contact: scripts/projections) */
  int32_t type; /**< cj_contact_type */
  int32_t base; /**< cj_base */
  double p_WCj[3]; /**< contact point on the journal */
  double p_WCi[3]; /**< contact point on the bearing */
  double normal_W[3];
  double depth;
  double depth_error_bound;
  double p_WCj_error_bound;
  double p_WCi_error_bound;
  /** Rim crossings bounding the penetration arc (point contacts); none for line and face
   * contacts. */
  cj_crossing crossings[2];
  int32_t crossing_count;
  int32_t reserved0;
  cj_certificate certificate;
  double reserved[4];
  /* END GENERATED cj_contact members */
} cj_contact;

#define CJ_MAX_CONTACTS 6

/** The answer of a detection (C++: JointContacts). contacts[0, contact_count) are set, radial
 * before axial, base A before B; the entries after them are left as they were. */
typedef struct cj_result {
  /* BEGIN GENERATED cj_result members (the field list of JointContacts: scripts/projections) */
  int32_t scenario; /**< cj_scenario */
  int32_t aligned; /**< 1 when the axes are (treated as) parallel */
  int32_t contact_count; /**< 0 to CJ_MAX_CONTACTS */
  int32_t reserved0;
  /** The weakest certificate over every decision taken, "no contact" answers included. */
  cj_certificate certificate;
  cj_contact contacts[CJ_MAX_CONTACTS];
  double reserved[8];
  /* END GENERATED cj_result members */
} cj_result;

/* ---- Detection -------------------------------------------------------------------------------- */

/**
 * Detect every contact between a journal and its bearing (C++: detect_contacts).
 * On CJ_OK `*result` holds the answer; on any other status `*result` is untouched.
 * `options` may be NULL (cj_default_options()).
 */
CJ_API cj_status cj_detect(const cj_dimensions* dimensions, const cj_pose* bearing,
                           const cj_pose* journal, const cj_options* options, cj_result* result,
                           char* message, size_t message_capacity);

/**
 * `count` poses read in place from the caller's arrays: pose k's component c (c = 0, 1, 2 for
 * p_WP x, y, z, then 3, 4, 5 for axis_W x, y, z) is the double at byte address
 *   (const char*)component[c] + k * stride.
 * The stride is in bytes (so that an array of the caller's own structs works as well as an array
 * of doubles) and may be 0 (the same pose for every k) or negative.
 *   row-major count x 6 doubles `d`:   component[c] = d + c,         stride = 6 * sizeof(double)
 *   column-major (MATLAB, Fortran's d(count, 6)): component[c] = d + c * count, stride = sizeof(double)
 *   six separate arrays x, y, z, ax, ay, az: component = {x, y, z, ax, ay, az}, stride = sizeof(double)
 * cj_pose_array_rows() and cj_pose_array_columns() fill in the first two.
 */
typedef struct cj_pose_array {
  const double* component[6];
  ptrdiff_t stride;
} cj_pose_array;

/** Row-major count x 6 doubles (pose k is data[6k .. 6k+5]; also a contiguous cj_pose array). */
CJ_API cj_pose_array cj_pose_array_rows(const double* data);
/** Column-major count x 6 doubles (pose k is data[k], data[k + count], ..., data[k + 5 count]). */
CJ_API cj_pose_array cj_pose_array_columns(const double* data, size_t count);
/** One pose for every k (stride 0). */
CJ_API cj_pose_array cj_pose_array_repeat(const cj_pose* pose);

/**
 * cj_detect for poses k = 0 .. count-1: results[k] is the answer for bearings k and journals k.
 * Stops at the first pose that fails: results before it are set, results from it on untouched,
 * the message names the pose ("poses[17]: journal.axis_W = [0, 0, 0]: must not be the zero
 * vector"), and `*processed` (when not NULL) receives the number of results set (count on CJ_OK).
 * A count larger than any array of cj_result can be (PTRDIFF_MAX bytes) is CJ_INVALID_INPUT
 * naming `count`.
 */
CJ_API cj_status cj_detect_many(const cj_dimensions* dimensions, const cj_pose_array* bearings,
                                const cj_pose_array* journals, size_t count,
                                const cj_options* options, cj_result* results, size_t* processed,
                                char* message, size_t message_capacity);

/* ---- The pin-in-hole joint -------------------------------------------------------------------- */

/** One axial stop of a pin: the inner face of a head, collar or washer, a plane perpendicular to
 * the pin's axis at `position` along it from the pin's point P (positive: on the side the pin's
 * axis points to), bounded by a circle of radius `outer_radius` (C++: AxialStop). */
typedef struct cj_axial_stop {
  double position;
  double outer_radius;
} cj_axial_stop;

#define CJ_MAX_AXIAL_STOPS 2

/** A pin longer than the hole it passes through (C++: PinInHoleDimensions): hole radius Rh and
 * the hole's length L between the link's two faces, pin radius Rp, and `stop_count` (0, 1 or 2)
 * axial stops, stops[0, stop_count) read. Valid when Rh > Rp > 0, L > 0, each in [1e-150,
 * 1e150] (see cj_dimensions), each stop outside the hole (|position| > L/2) and larger than it
 * (outer_radius > Rh), two stops on opposite sides of P; otherwise cj_detect_pin_in_hole returns
 * CJ_INVALID_INPUT naming the field ("dimensions.stops[1].outer_radius = ..."). */
typedef struct cj_pin_in_hole_dimensions {
  double hole_radius;
  double hole_length;
  double pin_radius;
  int32_t stop_count;
  /** Must be zero (see the ABI rules). */
  int32_t reserved0;
  cj_axial_stop stops[CJ_MAX_AXIAL_STOPS];
  /** Must be zero (see the ABI rules). */
  double reserved[4];
} cj_pin_in_hole_dimensions;

/** The answer of a pin-in-hole detection (C++: PinInHoleContacts). Each contact is a cj_contact
 * with the link (the hole) for the bearing and the pin for the journal: p_WCj on the pin, p_WCi
 * on the link, normal_W the direction the pin penetrates the link; type radial: an edge or line
 * contact, axial: a stop; base a, b: at link face A (the face the hole's axis points to) or B,
 * mid: the line contact; crossings bound the contact's arc on the circle that bounds it (a hole
 * edge circle or a stop's outer circle), in that circle's frame. contacts[0, contact_count) are
 * set; the entries after them are left as they were. */
typedef struct cj_pin_in_hole_result {
  /* BEGIN GENERATED cj_pin_in_hole_result members (the field list of PinInHoleContacts: scripts/projections) */
  int32_t scenario; /**< cj_pin_in_hole_scenario */
  int32_t aligned; /**< 1 when the axes are (treated as) parallel */
  int32_t contact_count; /**< 0 to CJ_MAX_CONTACTS */
  int32_t reserved0;
  /** The weakest certificate over every decision taken, "no contact" answers included. */
  cj_certificate certificate;
  /** Radial (edges, line) before axial (stops, faces), face A before B. */
  cj_contact contacts[CJ_MAX_CONTACTS];
  double reserved[8];
  /* END GENERATED cj_pin_in_hole_result members */
} cj_pin_in_hole_result;

/**
 * Detect every contact between a pin (pose `pin`: P, the pin point at the hole's centre when
 * centred, and its axis) and the hole it passes through (pose `hole`: the hole's centre, midway
 * between the link's faces, and its axis) (C++: detect_pin_in_hole_contacts). On CJ_OK `*result`
 * holds the answer; on any other status `*result` is untouched and the message names the field
 * ("dimensions.pin_radius = ...", "hole.axis_W = ...", "pin.p_WP = ..."). `options` may be NULL
 * (cj_default_options()).
 */
CJ_API cj_status cj_detect_pin_in_hole(const cj_pin_in_hole_dimensions* dimensions,
                                       const cj_pose* hole, const cj_pose* pin,
                                       const cj_options* options, cj_pin_in_hole_result* result,
                                       char* message, size_t message_capacity);

/**
 * cj_detect_pin_in_hole for poses k = 0 .. count-1, read in place as cj_detect_many reads its
 * poses (cj_pose_array; cj_pose_array_repeat() for a hole that stays put): results[k] is the
 * answer for holes k and pins k, bit for bit the answer of cj_detect_pin_in_hole on that pose.
 * The dimensions and options are checked once, before any pose. Stops at the first pose that
 * fails: results before it are set, results from it on untouched, the message names the pose
 * ("poses[17]: pin.axis_W = [0, 0, 0]: must not be the zero vector"), and `*processed` (when not
 * NULL) receives the number of results set (count on CJ_OK). A count larger than any array of
 * cj_pin_in_hole_result can be (PTRDIFF_MAX bytes) is CJ_INVALID_INPUT naming `count`.
 */
CJ_API cj_status cj_detect_pin_in_hole_many(const cj_pin_in_hole_dimensions* dimensions,
                                            const cj_pose_array* holes, const cj_pose_array* pins,
                                            size_t count, const cj_options* options,
                                            cj_pin_in_hole_result* results, size_t* processed,
                                            char* message, size_t message_capacity);

/* ---- Kernel queries --------------------------------------------------------------------------- */

/** { x : normal . (x - center) = 0, |x - center| = radius }, radius > 0, normal != 0. */
typedef struct cj_circle {
  double center[3];
  double normal[3];
  double radius;
} cj_circle;

/** { x : normal . (x - point) = 0 }; the side `normal` points to is positive. normal != 0. */
typedef struct cj_plane {
  double point[3];
  double normal[3];
} cj_plane;

/** The lateral surface { x : |(x - axis_point) x axis| = radius |axis| }, radius > 0. */
typedef struct cj_cylinder {
  double axis_point[3];
  double axis[3];
  double radius;
} cj_cylinder;

/** Rim points with angle in the counter-clockwise sweep from begin to end (rim_arc.hpp). */
typedef struct cj_arc {
  double begin;
  double end;
  int32_t full;
  int32_t reserved;
} cj_arc;

/** C++: CirclePlaneIntersection. */
typedef struct cj_circle_plane_result {
  int32_t topology; /**< cj_circle_plane_topology */
  int32_t side;     /**< +1, -1 or 0 (intersect_circle_plane.hpp) */
  cj_crossing crossings[2];
  int32_t crossing_count;
  int32_t has_penetration;
  cj_arc penetration;
  double max_signed_distance;
  double max_signed_distance_error_bound;
  cj_certificate certificate;
  double reserved[4];
} cj_circle_plane_result;

/** C++: CircleCylinderIntersection. */
typedef struct cj_circle_cylinder_result {
  int32_t topology; /**< cj_circle_cylinder_topology */
  int32_t crossing_count;
  cj_crossing crossings[4];
  cj_arc penetration_arcs[2];
  int32_t arc_count;
  int32_t reserved0;
  cj_certificate certificate;
  double reserved[4];
} cj_circle_cylinder_result;

/** A journal rim against a bearing base plane (eqs. 11-15). Only `certify` and `exact_fallback`
 * of `options` (may be NULL) apply. On failure `*result` is untouched. */
CJ_API cj_status cj_intersect_circle_plane(const cj_circle* circle, const cj_plane* plane,
                                           const cj_options* options,
                                           cj_circle_plane_result* result, char* message,
                                           size_t message_capacity);

/** A journal rim against the bearing's lateral wall (eqs. 16-21). As above. */
CJ_API cj_status cj_intersect_circle_cylinder(const cj_circle* circle, const cj_cylinder* cylinder,
                                              const cj_options* options,
                                              cj_circle_cylinder_result* result, char* message,
                                              size_t message_capacity);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif /* CLEARJOINT_CLEARJOINT_H */
