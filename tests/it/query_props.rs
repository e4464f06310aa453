//! Property tests of the parser: it never panics, and printing an AST
//! then parsing it gives the same AST.

use nrgdb::model::{SpaceId, SpaceKind};
use nrgdb::query::{
    CompareOp, Condition, Field, KEYWORDS, OrderKey, SpaceRef, Statement, Value, WalkOptions,
    parse, parse_statement,
};
use proptest::prelude::*;

fn number() -> impl Strategy<Value = f64> {
    prop_oneof![
        -1e6..1e6f64,
        (-1000i32..1000).prop_map(f64::from),
        Just(1e-7),
        Just(2.5e20)
    ]
}

fn text() -> impl Strategy<Value = String> {
    "[a-zA-Z0-9 _\"'\\\\%-]{0,10}"
}

fn space_ref() -> impl Strategy<Value = SpaceRef> {
    let kind = prop_oneof![
        Just(None),
        proptest::sample::select(SpaceKind::ALL.to_vec()).prop_map(Some)
    ];
    prop_oneof![
        (kind, any::<u32>()).prop_map(|(kind, id)| SpaceRef::Id {
            kind,
            id: SpaceId(id)
        }),
        text().prop_map(SpaceRef::Name),
        (number(), number()).prop_map(|(x, y)| SpaceRef::Point([x, y])),
    ]
}

fn field() -> impl Strategy<Value = Field> {
    prop_oneof![
        Just(Field::Id),
        Just(Field::Kind),
        Just(Field::Name),
        Just(Field::Area),
        Just(Field::Degree),
        Just(Field::Width),
        Just(Field::Level),
        text().prop_map(Field::Attr),
    ]
}

fn condition() -> impl Strategy<Value = Condition> {
    let op = proptest::sample::select(vec![
        CompareOp::Eq,
        CompareOp::Ne,
        CompareOp::Lt,
        CompareOp::Le,
        CompareOp::Gt,
        CompareOp::Ge,
        CompareOp::Like,
    ]);
    let value = prop_oneof![
        number().prop_map(Value::Number),
        text().prop_map(Value::Text),
        any::<bool>().prop_map(Value::Bool),
        Just(Value::Null),
    ];
    let leaf =
        (field(), op, value).prop_map(|(field, op, value)| Condition::Compare { field, op, value });
    leaf.prop_recursive(4, 16, 2, |inner| {
        prop_oneof![
            (inner.clone(), inner.clone())
                .prop_map(|(a, b)| Condition::And(Box::new(a), Box::new(b))),
            (inner.clone(), inner.clone())
                .prop_map(|(a, b)| Condition::Or(Box::new(a), Box::new(b))),
            inner.prop_map(|a| Condition::Not(Box::new(a))),
        ]
    })
}

fn statement() -> impl Strategy<Value = Statement> {
    let refs = || proptest::collection::vec(space_ref(), 0..3);
    let kind = prop_oneof![
        Just(None),
        proptest::sample::select(SpaceKind::ALL.to_vec()).prop_map(Some)
    ];
    let order = proptest::collection::vec(
        (field(), any::<bool>()).prop_map(|(field, descending)| OrderKey { field, descending }),
        0..3,
    );
    prop_oneof![
        (
            space_ref(),
            space_ref(),
            refs(),
            refs(),
            // The parser takes 1 to MAX_ALTERNATIVES.
            proptest::option::of(1..=nrgdb::route::MAX_ALTERNATIVES as u32),
            walk_options()
        )
            .prop_map(
                |(from, to, via, avoid, alternatives, with)| Statement::Route {
                    avoid_where: None,
                    from,
                    to,
                    via,
                    avoid,
                    alternatives,
                    with,
                }
            ),
        (space_ref(), proptest::option::of(any::<u32>()))
            .prop_map(|(of, depth)| Statement::Neighbours { of, depth }),
        (
            kind,
            proptest::option::of(condition()),
            order,
            proptest::option::of(any::<u64>())
        )
            .prop_map(|(kind, filter, order, limit)| Statement::Find {
                kind,
                filter,
                order,
                limit
            }),
        (number(), number(), proptest::option::of(text())).prop_map(|(x, y, level)| {
            Statement::Locate {
                point: [x, y],
                level,
            }
        }),
        (space_ref(), number(), walk_options()).prop_map(|(from, within_m, with)| {
            Statement::Reachable {
                from,
                within_m,
                with,
            }
        }),
        Just(Statement::ShowMaps),
        proptest::option::of(text()).prop_map(|map| Statement::ShowRevisions { map }),
        (text(), proptest::option::of(any::<u64>()))
            .prop_map(|(map, revision)| Statement::Use { map, revision }),
        // Names are never empty (or blank).
        (
            space_ref(),
            "[a-zA-Z0-9_\"'\\\\%-][a-zA-Z0-9 _\"'\\\\%-]{0,9}"
        )
            .prop_map(|(space, name)| Statement::Name { space, name }),
        (any::<u64>(), any::<u64>()).prop_map(|(from, to)| Statement::Diff { from, to }),
    ]
    .prop_flat_map(|s| prop_oneof![Just(s.clone()), Just(Statement::Explain(Box::new(s)))])
}

fn soup() -> impl Strategy<Value = String> {
    let piece = prop_oneof![
        proptest::sample::select(KEYWORDS.to_vec()).prop_map(String::from),
        Just("(".to_string()),
        Just(")".to_string()),
        Just(",".to_string()),
        Just(";".to_string()),
        Just("\"".to_string()),
        Just("--".to_string()),
        Just(".".to_string()),
        Just("\n".to_string()),
        "[a-z]{1,6}",
        "-?[0-9]{1,4}(\\.[0-9]{1,3})?",
        "[=<>!]{1,2}",
    ];
    proptest::collection::vec(piece, 0..25).prop_map(|v| v.join(" "))
}

fn walk_options() -> impl Strategy<Value = WalkOptions> {
    (
        proptest::option::of(number()),
        proptest::option::of(number()),
        proptest::option::of(number()),
        any::<bool>(),
        any::<bool>(),
    )
        .prop_map(
            |(clearance_m, min_door_width_m, speed_m_s, no_stairs, no_elevator)| WalkOptions {
                clearance_m,
                min_door_width_m,
                speed_m_s,
                no_stairs,
                no_elevator,
            },
        )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]

    #[test]
    fn parser_never_panics(s in "\\PC{0,200}") {
        let _ = parse(&s);
    }

    #[test]
    fn parser_never_panics_on_token_soup(s in soup()) {
        if let Err(e) = parse(&s) {
            let span = e.span().expect("syntax errors carry a span");
            prop_assert!(span.offset <= s.len());
        }
    }

    #[test]
    fn display_round_trips(ast in statement()) {
        let text = ast.to_string();
        let back = parse_statement(&text);
        prop_assert!(back.is_ok(), "{text}: {back:?}");
        prop_assert_eq!(back.unwrap(), ast, "{}", text);
    }
}
