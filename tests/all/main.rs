//! The integration tests, one binary (linked once): a module per subject, the shared
//! builders in `common` and the in-process FMI master in `fmu`.

mod common;
mod counting;
mod fmu;

mod architecture;
mod bad_input;
mod budget;
mod cli;
mod cli_words;
mod configuration;
mod default_platform;
mod directional;
mod drag_current;
mod dynamics;
mod fmi2_abi;
mod fmi2_alloc;
mod fmi2_bounds;
mod fmi2_limits;
mod fmi2_misuse;
mod fmi2_state;
mod fmi2_step_bounds;
mod fmi2_symbols;
mod fmu_configuration;
mod full_qtf;
mod full_qtf_directions;
mod fuzz;
mod montecarlo;
mod nemoh;
mod nemoh_rao;
mod newman;
mod oscillator;
mod quirks;
mod rao;
mod reading_cost;
mod references;
mod sea_state;
mod simulation;
mod stream;
mod studies;
mod unphysical;
mod user_data;
mod wamit;
mod wamit_directions;
mod wave_frequency;
mod yaw_following;
