#!/usr/bin/env python3
"""Prints the workspace's `[profile.*]` tables (Cargo.toml) as a Cargo
configuration file, for `cargo --config FILE` in a crate outside the
workspace: built with the same profiles into the same target folder, the
crate reuses the dependencies the workspace compiled (CI's own-vehicle
build). Cargo.toml stays the one owner of the profiles."""

import sys
import tomllib


def value(v):
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, (int, float)):
        return str(v)
    return '"%s"' % v


def main():
    manifest = sys.argv[1] if len(sys.argv) > 1 else "Cargo.toml"
    with open(manifest, "rb") as f:
        profiles = tomllib.load(f).get("profile", {})
    for name, table in profiles.items():
        for key, v in table.items():
            if key == "package":
                for package, settings in v.items():
                    for k, vv in settings.items():
                        print(f'profile.{name}.package."{package}".{k} = {value(vv)}')
            elif isinstance(v, dict):
                for k, vv in v.items():
                    print(f"profile.{name}.{key}.{k} = {value(vv)}")
            else:
                print(f"profile.{name}.{key} = {value(v)}")


if __name__ == "__main__":
    main()
