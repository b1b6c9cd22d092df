"""Runs (case, seed) through SlowDrift.fmu with fmpy: one instance, created on first use and
reused for every later run through fmi2Reset (a fresh instance only if the reset fails).

A run: fmi2Reset (from the second run on), fmi2SetupExperiment(startTime, stopTime) with the
case's times, every FMU parameter of the case plus `seed`, initialisation, then `steps`
fmi2DoStep calls of h = time_step from t = startTime + k h with no external force (the
inputs keep their zero start values), reading X, Y, theta at t = 0 and after each step:
the record of the native `run_seed` (src/montecarlo/mod.rs), summarised by `stats`.
An FMI call that fails makes the run fail with the FMU's logged error messages (the
core's message, as the native tool records it)."""

from ctypes import byref

from .errors import RunFailed
from .stats import StatisticsError, run_statistics

POSITIONS = ("X", "Y", "theta")
# fmi2Status at or above which a log line is an error.
FMI2_ERROR = 3


class FmuRunner:
    """One SlowDrift.fmu instance (not thread-safe: one per worker thread)."""

    def __init__(self, fmu_path, unzip_dir, name="slowdrift_dask"):
        from fmpy import extract, read_model_description

        self.md = read_model_description(fmu_path)
        self.unzip_dir = extract(fmu_path, unzipdir=unzip_dir)
        self.name = name
        self.variables = {v.name: v for v in self.md.modelVariables}
        self.positions = [self.variables[n].valueReference for n in POSITIONS]
        self.errors = []
        self.slave = None
        self.used = False
        # Runs made and instances created by this runner (reported to the tests).
        self.runs = 0
        self.instances = 0
        self._instantiate()

    def _log(self, _environment, _instance, status, _category, message):
        if status >= FMI2_ERROR:
            self.errors.append(message.decode("utf-8", "replace"))

    def _instantiate(self):
        from fmpy.fmi2 import (FMU2Slave, defaultCallbacks, fmi2CallbackFunctions,
                               fmi2CallbackLoggerTYPE)
        from fmpy.logging import addLoggerProxy

        callbacks = fmi2CallbackFunctions()
        callbacks.logger = fmi2CallbackLoggerTYPE(self._log)
        callbacks.allocateMemory = defaultCallbacks.allocateMemory
        callbacks.freeMemory = defaultCallbacks.freeMemory
        # The FMU's logger is variadic in C; fmpy's proxy formats the message for Python.
        addLoggerProxy(byref(callbacks))
        self.callbacks = callbacks  # kept alive as long as the instance
        self.slave = FMU2Slave(guid=self.md.guid, unzipDirectory=self.unzip_dir,
                               modelIdentifier=self.md.coSimulation.modelIdentifier,
                               instanceName=self.name)
        self.slave.instantiate(callbacks=callbacks)
        self.used = False
        self.instances += 1

    def _set(self, name, value):
        v = self.variables[name]
        if v.type == "Real":
            self.slave.setReal([v.valueReference], [float(value)])
        elif v.type == "Integer":
            self.slave.setInteger([v.valueReference], [int(value)])
        elif v.type == "String":
            self.slave.setString([v.valueReference], [str(value)])
        else:
            raise TypeError(f"FMU parameter {name}: type {v.type} not handled")

    def _fresh(self):
        """Back to the instantiated state: fmi2Reset, or a new instance if that fails."""
        from fmpy.fmi1 import FMICallException

        if not self.used:
            return
        try:
            self.slave.reset()
            self.used = False
        except FMICallException:
            self.close()
            self._instantiate()

    def run(self, case, seed):
        """The 12 statistics of (case, seed); RunFailed when the FMU refuses or fails."""
        from fmpy.fmi1 import FMICallException

        if case.fmu_parameters is None:
            raise RunFailed(f"the FMU cannot run case '{case.name}': {case.fmu_unavailable}")
        self._fresh()
        self.used = True
        self.runs += 1
        self.errors.clear()
        h, t0 = case.time_step, case.start_time
        s = self.slave
        try:
            s.setupExperiment(startTime=t0, stopTime=case.stop_time)
            for name, value in case.fmu_parameters.items():
                self._set(name, value)
            self._set("seed", seed)
            s.enterInitializationMode()
            s.exitInitializationMode()
            records = ([], [], [])
            for k in range(case.steps + 1):
                if k > 0:
                    s.doStep(currentCommunicationPoint=t0 + (k - 1) * h,
                             communicationStepSize=h)
                for record, value in zip(records, s.getReal(self.positions)):
                    record.append(value)
        except FMICallException as e:
            # The FMU logs "<function>: <the core's message>"; the run's error is the core's
            # message, as the native tool records it.
            prefix = f"{e.function}: "
            messages = [m.removeprefix(prefix) for m in self.errors]
            raise RunFailed("; ".join(messages) or str(e)) from None
        try:
            return run_statistics(*records, h, case.transient)
        except StatisticsError as e:
            raise RunFailed(str(e)) from None

    def close(self):
        if self.slave is not None:
            try:
                self.slave.terminate()
            except Exception:  # noqa: BLE001 - terminate is refused in some states
                pass
            self.slave.freeInstance()
            self.slave = None
