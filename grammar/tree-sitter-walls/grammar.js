/**
 * Tree-sitter grammar for the walls file of pkdgrav (see ../walls.ebnf, the normative
 * grammar). Keywords and type names match regardless of case. The grammar is tolerant,
 * as an editor needs: values that do not fit are still values, unknown words are
 * `word` nodes, and `walls-lint` reports what is wrong.
 *
 * Tokens: no precedences, so the longest match wins (`walls` is a word, not `wall`
 * and `s`); on a tie the rule defined first wins (`wall` is the keyword, `1` a number).
 */

// A case-insensitive pattern for a keyword.
const ci = (word) =>
  new RegExp(
    word
      .split('')
      .map((c) => (/[a-z]/.test(c) ? `[${c}${c.toUpperCase()}]` : c.replace(/[-]/g, '\\-')))
      .join(''),
  );

const GENERAL = [
      'time',
      'lengthunit',
      'massunit',
      'timeunit',
];

const PROPERTIES = [
      'inner_overlap_boundary',
      'cohesion_model',
      'cohesive_coeff',
      'transparency',
      'hole-radius',
      'open-angle',
      'osc-phase',
      'ang-speed',
      'k_n_outer',
      'k_t_outer',
      'k_n_inner',
      'k_t_inner',
      'velocity',
      'osc-ampl',
      'osc-freq',
      'assembly',
      'vertex1',
      'vertex2',
      'osc-vec',
      'rot-vec',
      'ixj-vec',
      'iyj-vec',
      'izj-vec',
      'pxj-vec',
      'pyj-vec',
      'pzj-vec',
      'origin',
      'orient',
      'radius',
      'length',
      'beta_s',
      'taper',
      'color',
      'type',
      'step',
      'epsn',
      'epst',
      'mu_s',
      'mu_r',
      'mu_t',
      'mass',
      'k_n',
      'k_t',
      'cog',
];

const TYPES = [
      'cylinder-infinite',
      'cylinder-finite',
      'rectangle',
      'triangle',
      'plane',
      'shell',
      'disk',
      'disc',
];

module.exports = grammar({
  name: 'walls',

  // Separators: C's white space (space, tab, newline, vertical tab, form feed, carriage
  // return), and `,` and `=`, which pkdgrav reads as spaces. A byte-order mark is an
  // error to the toolkit (S005), read as if absent.
  extras: ($) => [/[ \t\r\n\v\f,=\uFEFF]+/, $.comment],

  rules: {
    source_file: ($) => repeat(choice($.wall_block, $.defaults_block, $.general_statement, $.property, $.value)),

    wall_block: ($) => prec.right(seq($.wall_keyword, repeat($.property))),

    defaults_block: ($) =>
      prec.right(seq($.defaults_keyword, repeat(choice($.property, $.general_statement)))),

    general_statement: ($) => prec.right(seq($.general_keyword, repeat($.value))),

    property: ($) => prec.right(seq($.property_name, repeat($.value))),

    value: ($) => choice($.number, $.type_name, $.word),

    wall_keyword: (_) => token(ci('wall')),
    defaults_keyword: (_) => token(ci('defaults')),
    general_keyword: (_) => token(choice(...GENERAL.map(ci))),
    property_name: (_) => token(choice(...PROPERTIES.map(ci))),
    type_name: (_) => token(choice(...TYPES.map(ci))),

    // A decimal real: sign, digits with optional fraction (or a leading point), exponent.
    number: (_) => token(/[+-]?([0-9]+(\.[0-9]*)?|\.[0-9]+)([eE][+-]?[0-9]+)?/),

    // Anything else between separators: unknown words, malformed numbers.
    word: (_) => token(/[^ \t\r\n\v\f,=#!\uFEFF]+/),

    // A comment from `#` or `!` to the end of the line.
    comment: (_) => token(seq(/[#!]/, /[^\r\n]*/)),
  },
});
