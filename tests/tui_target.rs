//! The target in the explorer's form (`m`, issue 33): M and v_t typed like every other input,
//! the run then the pair's — the library's `collide` on a rigid target — and `inf` the wall
//! again, today's run to the bit; speeds that never close are refused, the setting kept.

mod tui_common;

use bouncelab::Ball;
use bouncelab::preset::Preset;
use bouncelab::target::Target;
use bouncelab::tui::action::Action;
use bouncelab::tui::app::{App, Overlay};
use bouncelab::tui::physical::Field;
use ratatui::crossterm::event::KeyCode;

use tui_common::*;

/// Open the form, go to `field`, type `text` over its value and press Enter.
fn set(app: &mut App, field: Field, text: &str) {
    if !matches!(app.overlay(), Overlay::Form(_)) {
        press(app, &[KeyCode::Char('m')]);
    }
    let Overlay::Form(f) = app.overlay() else {
        panic!("no form")
    };
    let n = Field::ALL.len();
    let to = Field::ALL.iter().position(|&g| g == field).unwrap();
    let at = Field::ALL.iter().position(|&g| g == f.selected).unwrap();
    press(app, &vec![KeyCode::Down; (to + n - at) % n]);
    press(app, &[KeyCode::Enter]);
    app.update(Action::InputClear);
    press(app, &chars(text));
    press(app, &[KeyCode::Enter]);
}

#[test]
fn the_run_is_the_pairs_and_inf_is_the_wall_again() {
    let mut a = App::new(Preset::embedded().remove(0), true);
    let wall = a.run().unwrap().clone();
    set(&mut a, Field::TargetMass, "0.2");
    set(&mut a, Field::TargetSpeed, "1.5");
    assert_eq!(
        (a.setting().target_mass, a.setting().target_speed),
        (0.2, 1.5)
    );
    let ball = Ball::from_preset("superball").unwrap();
    let target = Target {
        mass: 0.2,
        speed: 1.5,
        ..Target::wall()
    };
    let pair = ball.collide(&target).unwrap().collision;
    let run = a.run().unwrap();
    assert!(
        (run.cor - pair.cor).abs() <= 1e-12 * pair.cor,
        "{} {}",
        run.cor,
        pair.cor
    );
    assert!((run.max_force - pair.max_force).abs() <= 1e-12 * pair.max_force);
    assert!(run.cor != wall.cor);
    // the form shows what was typed; ∞ for the wall
    let screen = screen_text(&draw(&a, 120, 40)).join("\n");
    assert!(screen.contains("v_t          1.5 m/s"), "{screen}");
    set(&mut a, Field::TargetSpeed, "0");
    set(&mut a, Field::TargetMass, "inf");
    assert_eq!(*a.run().unwrap(), wall);
    let screen = screen_text(&draw(&a, 120, 40)).join("\n");
    assert!(screen.contains("M              ∞ kg"), "{screen}");
    // two undoable changes each way
    assert_eq!(a.undo_depth(), 4);
}

#[test]
fn a_target_that_is_never_met_is_refused() {
    for (field, text, why) in [
        (Field::TargetSpeed, "-5", "never meet"),
        (Field::TargetMass, "0", "invalid target_mass: 0"),
        (Field::TargetMass, "-1", "invalid target_mass: -1"),
    ] {
        let mut a = App::new(Preset::embedded().remove(0), true);
        let before = a.setting().clone();
        set(&mut a, field, text);
        assert_eq!(*a.setting(), before, "{text} for {field:?}");
        let Overlay::Input(input) = a.overlay() else {
            panic!("the entry closed on {text}")
        };
        let error = input.error.clone().expect("a reason");
        assert!(error.contains(why), "{error:?} lacks {why:?}");
    }
    // v0 cannot be lowered below what a receding target needs to be met
    let mut a = App::new(Preset::embedded().remove(0), true);
    set(&mut a, Field::TargetSpeed, "-2");
    let before = a.setting().clone();
    set(&mut a, Field::V0, "1");
    assert_eq!(*a.setting(), before);
}
