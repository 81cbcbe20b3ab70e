//! The physical-inputs form (`m`): values checked as the command line's overrides check them
//! (refused with the range, never clamped), each accepted value one undoable change, and the
//! warning when a run leaves the model's validity (z_m or α_max beyond the radius R).

use crate::tui_common;
use crate::tui_common::superball;

use bouncelab::tui::action::{self, Action};
use bouncelab::tui::app::{App, Overlay, Severity};
use bouncelab::tui::param::Param;
use bouncelab::tui::physical::{self, Field};
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};

use tui_common::*;

const SIZES: [(u16, u16); 5] = [(80, 24), (100, 30), (120, 40), (160, 50), (200, 60)];

/// The superball with λ = 0.001 and ζ = 10 set in the form (which stays open): a ball whose
/// impact passes its radius (the form's validity warning).
fn soft_superball() -> App {
    let mut a = superball();
    set(&mut a, Field::Lambda, "0.001");
    set(&mut a, Field::Zeta, "10");
    a
}

fn key(app: &mut App, code: KeyCode) {
    if let Some(a) = action::from_key(KeyEvent::new(code, KeyModifiers::NONE), app.mode()) {
        app.update(a);
    }
}

fn typed(app: &mut App, text: &str) {
    for c in text.chars() {
        key(app, KeyCode::Char(c));
    }
}

/// Open the form, go to `field`, type `text` over its value and press Enter.
fn set(app: &mut App, field: Field, text: &str) {
    if !matches!(app.overlay(), Overlay::Form(_)) {
        key(app, KeyCode::Char('m'));
    }
    let n = Field::ALL.iter().position(|&f| f == field).unwrap();
    let Overlay::Form(f) = app.overlay() else {
        panic!("no form")
    };
    let at = Field::ALL.iter().position(|&g| g == f.selected).unwrap();
    for _ in 0..(n + Field::ALL.len() - at) % Field::ALL.len() {
        key(app, KeyCode::Down);
    }
    key(app, KeyCode::Enter);
    app.update(Action::InputClear);
    typed(app, text);
    key(app, KeyCode::Enter);
}

#[test]
fn an_accepted_value_is_one_undoable_change_and_the_form_comes_back() {
    let mut a = superball();
    let before = a.setting().clone();
    set(&mut a, Field::KP, "60000");
    assert_eq!(a.setting().params.k_p, 60000.0);
    // K_h follows K_p (Eq. 16), as `run --k-p` does
    let p = a.setting().params;
    assert_eq!(
        p.k_h,
        bouncelab::model::params::ImpactParams::k_h_matching(p.k_p, p.z_p)
    );
    assert!(matches!(a.overlay(), Overlay::Form(f) if f.selected == Field::KP));
    assert_eq!(a.undo_depth(), 1);
    // in g, as the readout shows it
    set(&mut a, Field::Mass, "50");
    assert_eq!(a.setting().params.mass, 0.05);
    assert_eq!(a.undo_depth(), 2);
    key(&mut a, KeyCode::Esc);
    assert_eq!(*a.overlay(), Overlay::None);
    key(&mut a, KeyCode::Char('u'));
    assert_eq!(a.setting().params.k_p, 60000.0);
    assert_eq!(a.setting().params.mass, before.params.mass);
    key(&mut a, KeyCode::Char('u'));
    assert_eq!(*a.setting(), before);
}

#[test]
fn a_value_out_of_range_is_refused_with_the_range_never_clamped() {
    for (field, text, range) in [
        (Field::KP, "-5", "1e-15 … 1e15 N/m"),
        (Field::C, "1e20", "1e-15 … 1e15 kg/s"),
        (Field::Mass, "0", "1e-12 … 1e18 g"),
        (Field::Radius, "-1", "1e-12 … 1e18 mm"),
        (Field::ZP, "1e999", "1e-12 … 1e18 mm"),
        (Field::E, "-5", "1e-15 … 1e15 Pa"),
        (Field::Lambda, "-1", "0 or 1e-15 … 1e6"),
        (Field::V0, "1000000000000000000", "range 1e-15 … 1e15"),
    ] {
        let mut a = superball();
        let before = a.setting().clone();
        set(&mut a, field, text);
        assert_eq!(
            *a.setting(),
            before,
            "{text} for {field:?} changed the setting"
        );
        assert_eq!(a.undo_depth(), 0);
        let Overlay::Input(input) = a.overlay() else {
            panic!("the entry closed on {text}")
        };
        let why = input.error.clone().expect("a reason");
        assert!(why.contains(range), "{why:?} lacks the range {range}");
        assert_eq!(a.message().unwrap().severity, Severity::Warning);
    }
}

#[test]
fn k_r_and_c_move_lambda_and_zeta_as_the_form_shows() {
    let mut a = superball();
    set(&mut a, Field::KR, "5450");
    assert!((a.setting().get(Param::Lambda) - 0.1).abs() < 1e-12);
    let p = a.setting().params;
    let d = physical::derived(&p);
    assert_eq!(d[0].1, (p.k_p / p.mass).sqrt());
    assert_eq!(d[1].1, p.z_p * (p.k_p / p.mass).sqrt() / p.v0);
}

/// The largest ball displacement and the peak indentation of the app's run.
fn peaks(a: &App) -> (f64, f64) {
    let r = a.run().unwrap();
    let alpha = r
        .history
        .displacement
        .iter()
        .copied()
        .fold(f64::MIN, f64::max);
    (r.max_indentation, alpha)
}

#[test]
fn the_validity_warning_appears_exactly_when_z_m_or_alpha_exceeds_r() {
    let mut a = superball();
    let r = a.setting().radius;
    let (z_m, alpha) = peaks(&a);
    assert!(z_m < r && alpha < r);
    assert_eq!(a.validity(), None);
    // λ = 0.001, ζ = 10: the recoil spring lets the ball travel
    set(&mut a, Field::Lambda, "0.001");
    set(&mut a, Field::Zeta, "10");
    let (z_m, alpha) = peaks(&a);
    assert!(z_m < r, "z_m {z_m} R {r}");
    assert!(alpha > r, "α {alpha} R {r}");
    let w = a.validity().expect("a warning");
    assert!(w.contains("α_max") && !w.contains("z_m"), "{w}");
    let mm = |x: f64| bouncelab::tui::format::value(x * 1e3);
    assert!(w.contains(&mm(alpha)) && w.contains(&mm(alpha - r)), "{w}");
    // the message and the readout say it
    assert!(a.message().unwrap().text.contains("outside the model"));
    // R just below α_max: α_max named; just above: no warning; just below z_m: z_m named
    set(&mut a, Field::Radius, &format!("{}", alpha * 0.999 * 1e3));
    let w = a.validity().expect("a warning");
    assert!(w.contains("α_max") && !w.contains("z_m"), "{w}");
    set(&mut a, Field::Radius, &format!("{}", alpha * 1.001 * 1e3));
    assert_eq!(a.validity(), None);
    set(&mut a, Field::Radius, &format!("{}", z_m * 0.999 * 1e3));
    let w = a.validity().expect("a warning");
    assert!(w.contains("z_m") && w.contains("α_max"), "{w}");
    set(&mut a, Field::Radius, &format!("{}", z_m * 1.001 * 1e3));
    let w = a.validity().expect("a warning");
    assert!(!w.contains("z_m") && w.contains("α_max"), "{w}");
}

#[test]
fn the_form_at_120x40_and_80x24() {
    let mut a = soft_superball();
    insta::assert_snapshot!("form_120x40", draw(&a, 120, 40).backend());
    key(&mut a, KeyCode::Esc);
    insta::assert_snapshot!("readout_outside_120x40", draw(&a, 120, 40).backend());
    let mut b = superball();
    key(&mut b, KeyCode::Char('m'));
    key(&mut b, KeyCode::Down);
    key(&mut b, KeyCode::Down);
    insta::assert_snapshot!("form_80x24", draw(&b, 80, 24).backend());
    key(&mut b, KeyCode::Enter);
    insta::assert_snapshot!("form_entry_80x24", draw(&b, 80, 24).backend());
}

#[test]
fn the_narrow_readout_at_80x24_keeps_the_warning() {
    let mut a = soft_superball();
    key(&mut a, KeyCode::Esc);
    key(&mut a, KeyCode::Char('['));
    assert!(!a.message().unwrap().text.contains("outside"));
    insta::assert_snapshot!("readout_outside_80x24", draw(&a, 80, 24).backend());
}

/// A ball changed in the form saves as it runs: its preset gives back the same parameters
/// and radius.
#[test]
fn a_saved_preset_keeps_the_form_values() {
    let mut a = superball();
    set(&mut a, Field::Mass, "50");
    set(&mut a, Field::Radius, "30");
    set(&mut a, Field::ZP, "3");
    let s = a.setting().clone();
    let (preset, _) = bouncelab::tui::save::preset_for(a.preset(), &s, "mine");
    let back = bouncelab::tui::setting::Setting::from_preset(s.preset, &preset);
    assert_eq!(back.params, s.params);
    assert_eq!(back.radius, 0.03);
}

/// E is the modulus K_p and z_p imply for an elastomer (K_p = 2π E z_p, Eq. 20): shown so, and
/// a typed E sets K_p to 2π E z_p with z_p kept and K_h following (as `run --k-p`), one
/// undoable change.
#[test]
fn e_is_the_modulus_k_p_and_z_p_imply_and_a_typed_e_sets_k_p() {
    let mut a = superball();
    let p = a.setting().params;
    let two_pi = 2.0 * std::f64::consts::PI;
    assert_eq!(Field::E.get(a.setting()), p.k_p / (two_pi * p.z_p));
    // the superball's adopted K_p and z_p imply E within 2 % of its material's 2.2 MPa
    assert!((Field::E.get(a.setting()) / 2.2e6 - 1.0).abs() < 0.02);
    set(&mut a, Field::E, "3e6");
    let q = a.setting().params;
    assert_eq!(q.k_p, two_pi * 3e6 * p.z_p);
    assert_eq!(q.z_p, p.z_p);
    assert_eq!(
        q.k_h,
        bouncelab::model::params::ImpactParams::k_h_matching(q.k_p, q.z_p)
    );
    assert!((Field::E.get(a.setting()) / 3e6 - 1.0).abs() < 1e-15);
    assert_eq!(a.undo_depth(), 1);
    key(&mut a, KeyCode::Esc);
    key(&mut a, KeyCode::Char('u'));
    assert_eq!(a.setting().params, p);
}

/// A metal ball's K_p follows its yield strength, not E: the field shows "—" and a typed E
/// is refused with the reason, nothing changed.
#[test]
fn a_metal_ball_has_no_e_to_type() {
    let mut s = superball().setting().clone();
    s.elastomer = false;
    assert!(Field::E.get(&s).is_nan());
    let why = Field::E.check(3e6, &s).unwrap_err();
    assert!(why.contains("metal") && why.contains("type K_p"), "{why}");
}

/// An entry opens holding its value, or empty: the wall's M (∞) opened as "—", and "0.8"
/// typed after it read "'—0.8' is not a number" (issue 51 item 2).
#[test]
fn an_entry_opens_holding_its_value_or_empty() {
    let mut a = superball();
    assert!(a.setting().target.mass.is_infinite());
    key(&mut a, KeyCode::Char('m'));
    let n = Field::ALL
        .iter()
        .position(|&f| f == Field::TargetMass)
        .unwrap();
    for _ in 0..n {
        key(&mut a, KeyCode::Down);
    }
    key(&mut a, KeyCode::Enter);
    let Overlay::Input(input) = a.overlay() else {
        panic!("no entry")
    };
    assert_eq!(input.text, "");
    typed(&mut a, "800");
    key(&mut a, KeyCode::Enter);
    assert_eq!(a.setting().target.mass, 0.8, "{:?}", a.message());
    // a finite value opens as itself, in g: Enter keeps it
    key(&mut a, KeyCode::Enter);
    let Overlay::Input(input) = a.overlay() else {
        panic!("no entry")
    };
    assert_eq!(input.text, "800");
}

/// One number format (issue 51 item 4): the form shows and takes m in g and R, z_p in mm as
/// the readout does, four significant digits (it showed `m 0.0374 kg`, `λ 1.29908`,
/// `E 2.16849e6` beside a readout's `m 37.40 g`); what it says back is in those units too,
/// and a refusal names the field as the form does (`M`, never the library's `target_mass`).
#[test]
fn the_form_speaks_the_readouts_units_and_digits() {
    let mut a = superball();
    key(&mut a, KeyCode::Char('m'));
    let shown = screen_text(&draw(&a, 120, 40)).join("\n");
    assert!(shown.contains("m        37.40 g"), "{shown}");
    assert!(shown.contains("z_p      4.000 mm"), "{shown}");
    assert!(
        !shown.contains(" kg ") && !shown.contains("1.29908"),
        "{shown}"
    );
    key(&mut a, KeyCode::Esc);
    set(&mut a, Field::Mass, "50");
    let said = a.message().unwrap().text.clone();
    assert_eq!(said, "m = 50.00 g");
    set(&mut a, Field::TargetMass, "0");
    let Overlay::Input(input) = a.overlay() else {
        panic!("the entry closed")
    };
    let why = input.error.clone().unwrap();
    assert!(
        why.starts_with("invalid M: 0 g (must be positive)"),
        "{why}"
    );
    assert!(!why.contains("target_mass"), "{why}");
}

/// Issue 51 item 6: with the validity warning showing both z_m and α_max, the form at
/// 80 × 24 lost its last lines (the warning's end and the hint "↑↓ field · Enter/= type · Esc
/// closes") below the screen. The fields scroll now: the selected field, the whole warning
/// and the hint are in the form whichever field is selected, at every size.
#[test]
fn the_form_with_a_warning_keeps_its_hint_and_selected_field_at_every_size() {
    let mut a = soft_superball();
    let (z_m, _) = peaks(&a);
    set(&mut a, Field::Radius, &format!("{}", z_m * 0.999 * 1e3));
    let warning = a.validity().expect("a warning");
    assert!(
        warning.contains("z_m") && warning.contains("α_max"),
        "{warning}"
    );
    // in the readout's one format: four significant digits (it wrote "z_m 0.128 mm")
    let z_m_mm = format!("z_m {}\u{a0}mm", bouncelab::tui::format::value(z_m * 1e3));
    assert!(warning.contains(&z_m_mm), "{z_m_mm:?} in {warning:?}");
    // the warning's last line as the form wraps it (46 wide: 43 for the text)
    let last = bouncelab::tui::format::wrap(&warning, 43).pop().unwrap();
    for (w, h) in SIZES {
        for field in Field::ALL {
            let n = Field::ALL.iter().position(|&f| f == field).unwrap();
            let Overlay::Form(f) = a.overlay() else {
                panic!("no form")
            };
            let at = Field::ALL.iter().position(|&g| g == f.selected).unwrap();
            for _ in 0..(n + Field::ALL.len() - at) % Field::ALL.len() {
                key(&mut a, KeyCode::Down);
            }
            // the form's own columns (46 wide, centred), not the readout beside it
            let t = draw(&a, w, h);
            let buf = t.backend().buffer();
            let x0 = (w - 46) / 2;
            let rows: Vec<String> = (0..h)
                .map(|y| (x0..x0 + 46).map(|x| buf[(x, y)].symbol()).collect())
                .collect();
            let s = rows.join("\n");
            assert!(s.contains("Esc closes"), "{w}×{h} {field:?}: no hint\n{s}");
            assert!(
                s.contains(last.trim()),
                "{w}×{h} {field:?}: warning cut\n{s}"
            );
            let selected = format!("▶{}", field.symbol());
            assert!(s.contains(&selected), "{w}×{h} {field:?}: not shown\n{s}");
        }
    }
    insta::assert_snapshot!("form_warning_80x24", draw(&a, 80, 24).backend());
}
