//! `modelDescription.xml`, for FMI 3.0 and 2.0, from the variables'
//! table ([`variables::table`](crate::variables::table)).

use std::fmt::Write;

use crate::plant::Plant;
use crate::variables::{Causality, Kind, Start, Variable};

/// The instantiation token (FMI 3.0) and GUID (FMI 2.0): the vehicle's
/// name and a 64-bit FNV-1a hash of every variable's name, type and
/// causality, so a library and a description of different vehicles or
/// versions refuse each other.
pub fn token<P: Plant>(table: &[Variable]) -> String {
    let mut hash: u64 = 0xcbf2_9ce4_8422_2325;
    let mut eat = |bytes: &[u8]| {
        for b in bytes {
            hash ^= u64::from(*b);
            hash = hash.wrapping_mul(0x0100_0000_01b3);
        }
    };
    eat(P::name().as_bytes());
    for v in table {
        eat(v.name.as_bytes());
        eat(&[v.kind as u8, v.causality as u8, 0xff]);
    }
    format!("{{trackgen-{}-{hash:016x}}}", identifier::<P>())
}

/// The model identifier: the model's name with every character that is
/// not a letter, a digit or `_` made `_` (it names the shared library).
pub fn identifier<P: Plant>() -> String {
    P::name()
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '_' {
                c
            } else {
                '_'
            }
        })
        .collect()
}

/// FMI 3.0's model description.
pub fn fmi3<P: Plant>(table: &[Variable]) -> String {
    let mut x = header::<P>(
        "3.0",
        &format!("instantiationToken=\"{}\"", token::<P>(table)),
    );
    let _ = writeln!(
        x,
        "  <CoSimulation modelIdentifier=\"{}\" canHandleVariableCommunicationStepSize=\"true\" \
         canReturnEarlyAfterIntermediateUpdate=\"false\" hasEventMode=\"false\" \
         canGetAndSetFMUState=\"false\" canSerializeFMUState=\"false\"/>",
        identifier::<P>()
    );
    units(&mut x, table);
    experiment::<P>(&mut x);
    x.push_str("  <ModelVariables>\n");
    for v in table {
        let tag = match v.kind {
            Kind::Float64 => "Float64",
            Kind::Int32 => "Int32",
            Kind::String => "String",
        };
        let _ = write!(x, "    <{tag} {}", attributes(v));
        if v.kind == Kind::Float64 && !v.unit.is_empty() && v.unit != "1" {
            let _ = write!(x, " unit=\"{}\"", v.unit);
        }
        match &v.start {
            Start::Float64(s) => {
                let _ = writeln!(x, " start=\"{s:?}\"/>");
            }
            Start::Int32(s) => {
                let _ = writeln!(x, " start=\"{s}\"/>");
            }
            Start::String(s) => {
                let _ = writeln!(x, ">\n      <Start value=\"{}\"/>\n    </{tag}>", escape(s));
            }
            Start::Computed => x.push_str("/>\n"),
        }
    }
    x.push_str("  </ModelVariables>\n  <ModelStructure>\n");
    for v in outputs(table) {
        let _ = writeln!(x, "    <Output valueReference=\"{}\"/>", v.value_reference);
    }
    for v in outputs(table) {
        let _ = writeln!(
            x,
            "    <InitialUnknown valueReference=\"{}\"/>",
            v.value_reference
        );
    }
    x.push_str("  </ModelStructure>\n</fmiModelDescription>\n");
    x
}

/// FMI 2.0's model description.
pub fn fmi2<P: Plant>(table: &[Variable]) -> String {
    let mut x = header::<P>(
        "2.0",
        &format!(
            "guid=\"{}\" numberOfEventIndicators=\"0\"",
            token::<P>(table)
        ),
    );
    let _ = writeln!(
        x,
        "  <CoSimulation modelIdentifier=\"{}\" canHandleVariableCommunicationStepSize=\"true\" \
         canNotUseMemoryManagementFunctions=\"true\" canGetAndSetFMUstate=\"false\" \
         canSerializeFMUstate=\"false\"/>",
        identifier::<P>()
    );
    units(&mut x, table);
    experiment::<P>(&mut x);
    x.push_str("  <ModelVariables>\n");
    for v in table {
        let _ = writeln!(x, "    <ScalarVariable {}>", attributes(v));
        let tag = match v.kind {
            Kind::Float64 => "Real",
            Kind::Int32 => "Integer",
            Kind::String => "String",
        };
        let _ = write!(x, "      <{tag}");
        if v.kind == Kind::Float64 && !v.unit.is_empty() && v.unit != "1" {
            let _ = write!(x, " unit=\"{}\"", v.unit);
        }
        match &v.start {
            Start::Float64(s) => {
                let _ = write!(x, " start=\"{s:?}\"");
            }
            Start::Int32(s) => {
                let _ = write!(x, " start=\"{s}\"");
            }
            Start::String(s) => {
                let _ = write!(x, " start=\"{}\"", escape(s));
            }
            Start::Computed => {}
        }
        x.push_str("/>\n    </ScalarVariable>\n");
    }
    x.push_str("  </ModelVariables>\n  <ModelStructure>\n    <Outputs>\n");
    // FMI 2.0 names a variable by its 1-based place in ModelVariables,
    // which is its value reference plus one here.
    for v in outputs(table) {
        let _ = writeln!(x, "      <Unknown index=\"{}\"/>", v.value_reference + 1);
    }
    x.push_str("    </Outputs>\n    <InitialUnknowns>\n");
    for v in outputs(table) {
        let _ = writeln!(x, "      <Unknown index=\"{}\"/>", v.value_reference + 1);
    }
    x.push_str("    </InitialUnknowns>\n  </ModelStructure>\n</fmiModelDescription>\n");
    x
}

fn header<P: Plant>(version: &str, identity: &str) -> String {
    format!(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n\
         <fmiModelDescription fmiVersion=\"{version}\" modelName=\"{}\" {identity} \
         description=\"{} ({}): a tracked vehicle compiled by trackgen\" \
         generationTool=\"trackgen {}\" variableNamingConvention=\"flat\">\n",
        escape(&P::name()),
        escape(&P::name()),
        P::summary(),
        env!("CARGO_PKG_VERSION"),
    )
}

fn attributes(v: &Variable) -> String {
    let (causality, variability) = match v.causality {
        Causality::Parameter => ("parameter", "fixed"),
        Causality::Input => ("input", "continuous"),
        Causality::Output => ("output", "continuous"),
        Causality::Independent => ("independent", "continuous"),
    };
    let variability = if v.kind == Kind::Float64 {
        variability
    } else {
        "fixed"
    };
    format!(
        "name=\"{}\" valueReference=\"{}\" causality=\"{causality}\" variability=\"{variability}\" description=\"{}\"",
        escape(&v.name),
        v.value_reference,
        escape(&v.description)
    )
}

fn outputs(table: &[Variable]) -> impl Iterator<Item = &Variable> {
    table.iter().filter(|v| v.causality == Causality::Output)
}

fn experiment<P: Plant>(x: &mut String) {
    let (stop, step) = P::default_experiment();
    let _ = writeln!(
        x,
        "  <DefaultExperiment startTime=\"0.0\" stopTime=\"{stop:?}\" stepSize=\"{step:?}\"/>"
    );
}

/// The SI units the variables use, by their base units' exponents.
fn units(x: &mut String, table: &[Variable]) {
    const UNITS: [(&str, &str); 15] = [
        ("m", "m=\"1\""),
        ("s", "s=\"1\""),
        ("m/s", "m=\"1\" s=\"-1\""),
        ("m/s2", "m=\"1\" s=\"-2\""),
        ("rad", "rad=\"1\""),
        ("deg", "rad=\"1\" factor=\"0.017453292519943295\""),
        ("rad/s", "rad=\"1\" s=\"-1\""),
        ("N", "kg=\"1\" m=\"1\" s=\"-2\""),
        ("N.s", "kg=\"1\" m=\"1\" s=\"-1\""),
        ("N.m", "kg=\"1\" m=\"2\" s=\"-2\""),
        ("N.m.s", "kg=\"1\" m=\"2\" s=\"-1\""),
        ("N.m/rad", "kg=\"1\" m=\"2\" s=\"-2\" rad=\"-1\""),
        ("N.m.s/rad", "kg=\"1\" m=\"2\" s=\"-1\" rad=\"-1\""),
        ("J", "kg=\"1\" m=\"2\" s=\"-2\""),
        ("W", "kg=\"1\" m=\"2\" s=\"-3\""),
    ];
    x.push_str("  <UnitDefinitions>\n");
    for (name, base) in UNITS {
        if table.iter().any(|v| v.unit == name) {
            let _ = writeln!(
                x,
                "    <Unit name=\"{name}\">\n      <BaseUnit {base}/>\n    </Unit>"
            );
        }
    }
    x.push_str("  </UnitDefinitions>\n");
}

/// Text as an XML attribute's value.
fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}
