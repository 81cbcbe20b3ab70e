//! `work`'s unit tests.

use super::*;

#[test]
fn the_limit_is_inclusive_and_weighs_the_law() {
    assert!(check(1_000_000, ContactLaw::Linear, "x").is_ok());
    assert!(check(1_000_001, ContactLaw::Linear, "x").is_err());
    assert!(check(25_000, ContactLaw::Hertz, "x").is_ok());
    let e = check(25_001, ContactLaw::ElasticPlastic, "25001 points").unwrap_err();
    assert_eq!(e.work, 1_000_040);
    assert_eq!(
        e.to_string(),
        "too much work: 25001 points is 25001 elastic-plastic-law impacts, worth 1000040 \
         against the work limit of 1000000 (an impact counts 1 with the linear law, 40 with \
         the others); ask for fewer points or values"
    );
}

#[test]
fn monte_carlo_samples_count_a_tenth_on_the_linear_law() {
    assert!(check_samples(10_000_000, ContactLaw::Linear).is_ok());
    let e = check_samples(10_000_001, ContactLaw::Linear).unwrap_err();
    assert_eq!(e.work, 1_000_001);
    assert!(e.to_string().starts_with(
        "too much work: 10000001 samples (10 linear-law samples count as one impact) is \
         1000001 linear-law impacts"
    ));
    // what mc's user can change: its samples, not "points or values" (issue 52's trial)
    assert!(e.to_string().ends_with("; ask for fewer samples"), "{e}");
    assert!(check_samples(25_000, ContactLaw::Hertz).is_ok());
    assert!(check_samples(25_001, ContactLaw::Hertz).is_err());
}

#[test]
fn hertz_samples_the_table_answers_count_a_fortieth() {
    assert!(check_samples_by(1_000_000, ContactLaw::Hertz, Nominal::Table).is_ok());
    let e = check_samples_by(1_000_001, ContactLaw::Hertz, Nominal::Table).unwrap_err();
    assert_eq!(e.work, 1_000_040);
    assert!(e.to_string().starts_with(
        "too much work: 1000001 samples (40 Hertz-law samples of a ball the Hertz table \
         answers count as one impact) is 25001 hertz-law impacts"
    ));
    // an untabulated ball keeps a whole impact a sample
    assert!(check_samples_by(25_001, ContactLaw::Hertz, Nominal::Solver).is_err());
    assert!(check_samples_by(25_001, ContactLaw::ElasticPlastic, Nominal::Solver).is_err());
}

/// `n` elements, `off` of them outside the Hertz table, `past` past yield.
fn elements(n: usize, off: usize, past: usize) -> Elements {
    Elements {
        n,
        off_table: off,
        past_yield: past,
    }
}

#[test]
fn elements_count_by_whether_the_hertz_table_holds_them() {
    let (linear, hertz) = (ContactLaw::Linear, ContactLaw::Hertz);
    // the linear law: as Monte Carlo samples, ten to an impact
    assert!(check_elements(linear, Elements::at_least(10_000_000)).is_ok());
    assert!(check_elements(linear, Elements::at_least(10_000_001)).is_err());
    // Hertz: 40 held elements to an impact, one outside the table a whole impact
    assert!(check_elements(hertz, Elements::at_least(1_000_000)).is_ok());
    let e = check_elements(hertz, Elements::at_least(1_000_001)).unwrap_err();
    assert!(e.to_string().starts_with(
        "too much work: 1000001 elements (40 elements the Hertz table holds count as one \
         impact) is 25001 hertz-law impacts"
    ));
    assert!(check_elements(hertz, elements(25_000, 25_000, 0)).is_ok());
    let e = check_elements(hertz, elements(30_000, 30_000, 0)).unwrap_err();
    assert_eq!(e.work, 1_200_000);
    assert!(e.to_string().starts_with(
        "too much work: 30000 elements (30000 of them outside the Hertz table, a whole \
         impact each; 40 of the others count as one impact) is 30000 hertz-law impacts"
    ));
    // 12 000 outside and 520 000 held: 12 000 + 13 000 impacts, at the limit
    assert!(check_elements(hertz, elements(532_000, 12_000, 0)).is_ok());
    assert!(check_elements(hertz, elements(532_001, 12_001, 0)).is_err());
    // a count of more outside than there are elements is all of them
    let e = check_elements(hertz, elements(30_000, usize::MAX, 0)).unwrap_err();
    assert_eq!(e.work, 1_200_000);
}

#[test]
fn elastic_plastic_elements_count_by_yield() {
    let ep = ContactLaw::ElasticPlastic;
    // below yield, the Hertz table's: 40 to an impact, so 10⁶ of them within the limit
    assert!(check_elements(ep, Elements::at_least(1_000_000)).is_ok());
    let e = check_elements(ep, Elements::at_least(1_000_001)).unwrap_err();
    assert_eq!(e.work, 1_000_040);
    assert!(e.to_string().starts_with(
        "too much work: 1000001 elements (40 elements the Hertz table holds below yield \
         count as one impact) is 25001 elastic-plastic-law impacts"
    ));
    // past yield, the Taylor steps': 20 to an impact
    assert!(check_elements(ep, elements(500_000, 0, 500_000)).is_ok());
    let e = check_elements(ep, elements(500_001, 0, 500_001)).unwrap_err();
    assert_eq!(e.work, 1_000_040);
    assert!(e.to_string().starts_with(
        "too much work: 500001 elements (500001 past yield, 20 to an impact; 40 of the \
         others count as one impact) is 25001 elastic-plastic-law impacts"
    ));
    // all three: 10 000 whole + 200 000 past yield (10 000) + 200 000 held (5 000)
    assert!(check_elements(ep, elements(410_000, 10_000, 200_000)).is_ok());
    let e = check_elements(ep, elements(410_001, 10_001, 200_000)).unwrap_err();
    assert!(e.to_string().starts_with(
        "too much work: 410001 elements (10001 of them outside the Hertz table, a whole \
         impact each; 200000 past yield, 20 to an impact; 40 of the others count as one \
         impact) is 25001 elastic-plastic-law impacts"
    ));
}

#[test]
fn elastic_plastic_samples_count_by_their_path() {
    let ep = ContactLaw::ElasticPlastic;
    // below yield: the Hertz table's cost, 1/40 of an impact
    assert!(check_samples_by(1_000_000, ep, Nominal::Table).is_ok());
    let e = check_samples_by(1_000_001, ep, Nominal::Table).unwrap_err();
    assert_eq!(e.work, 1_000_040);
    assert!(e.to_string().starts_with(
        "too much work: 1000001 samples (40 elastic-plastic-law samples of a ball the \
         Hertz table answers below yield count as one impact) is 25001"
    ));
    // past yield: the Taylor steps', 1/20
    assert!(check_samples_by(500_000, ep, Nominal::TaylorSteps).is_ok());
    let e = check_samples_by(500_001, ep, Nominal::TaylorSteps).unwrap_err();
    assert_eq!(e.work, 1_000_040);
    assert!(e.to_string().starts_with(
        "too much work: 500001 samples (20 elastic-plastic-law samples past yield count \
         as one impact) is 25001 elastic-plastic-law impacts"
    ));
    // the solver: a whole impact; the Taylor steps' count is the elastic–plastic law's
    assert!(check_samples_by(25_001, ep, Nominal::Solver).is_err());
    assert!(check_samples_by(25_001, ContactLaw::Hertz, Nominal::TaylorSteps).is_err());
}

#[test]
fn a_fit_takes_fewer_iterations_where_runs_cost_much_and_is_refused_below_ten() {
    // a 2 000-row trace, 640 history samples: runs of 1 × 8 + 20, the full 200 iterations
    let run = fit_run_cost(2_000, 640, ContactLaw::Linear);
    assert_eq!(run, 28);
    assert_eq!(
        fit_iterations(run, 5, 4, ContactLaw::Linear, String::new),
        Ok(200)
    );
    // 20 000 drop tests: a run is 20 000 impacts; even 10 iterations of 4 runs are too many
    let run = fit_run_cost(20_000, 0, ContactLaw::Linear);
    let e = fit_iterations(run, 2, 7, ContactLaw::Linear, || "20000 drops".into());
    let e = e.unwrap_err();
    assert!(e.work > LIMIT, "{e}");
    assert!(
        e.to_string()
            .starts_with("too much work: 20000 drops (7 starts"),
        "{e}"
    );
    // 300 COR points, 2 free: 1e6/7 per start, runs of 300 impacts, 5 to start and 4 an
    // iteration: (142 857 − 1 500)/1 200 = 117 iterations
    let run = fit_run_cost(300, 0, ContactLaw::Linear);
    assert_eq!(
        fit_iterations(run, 2, 7, ContactLaw::Linear, String::new),
        Ok(117)
    );
}

#[test]
fn a_hertz_trace_fit_is_held_to_fewer_iterations() {
    // 3 000 bins, 1 000 history samples, 6 variables: runs of 40 × 11 + 30 = 470, 4 starts
    // of (250 000 − 9 × 470)/(8 × 470) = 65 iterations
    let run = fit_run_cost(3_000, 1_000, ContactLaw::Hertz);
    assert_eq!(run, 470);
    assert_eq!(
        fit_iterations(run, 6, 4, ContactLaw::Hertz, String::new),
        Ok(65)
    );
}
