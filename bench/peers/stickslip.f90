!----------------------------------------------------------------------
! AUTO-07p equation file: the smooth part of the seed branch (eq. 3.5),
! slip below the belt only (s = v - x' > 0), cubic law (3.3):
!   x' = y,  y' = -2 beta y - x + mu(v - y),  mu(s) = mu_s - k1 s + k3 s^3.
! Time is scaled to [0,1] by the period T = PAR(6) (AUTO itself writes
! PAR(11) at a Hopf point, so the period lives elsewhere).
! PAR: 1 v, 2 beta, 3 mu_s, 4 k1, 5 k3, 6 T, 9 y(0) - v (PVLS);
! AUTO prints 11 digits, so PAR(7), PAR(8) (PVLS) carry the digits of v and
! T below 1e-5: v = round(PAR(1), 5) + PAR(7), T = round(PAR(6), 5) + PAR(8).
! Periodic orbits are a boundary-value problem (IPS = 4): u(0) = u(1)
! and y'(0) = 0 with y(0) the maximum of y, so y(0) - v = 0 (PAR(9))
! is the grazing point GR, located as a UZ point at mesh accuracy.
!----------------------------------------------------------------------

SUBROUTINE FIELD(U, PAR, F)
  IMPLICIT NONE
  DOUBLE PRECISION, INTENT(IN) :: U(2), PAR(*)
  DOUBLE PRECISION, INTENT(OUT) :: F(2)
  DOUBLE PRECISION s
  s = PAR(1) - U(2)
  F(1) = U(2)
  F(2) = -2*PAR(2)*U(2) - U(1) + PAR(3) - PAR(4)*s + PAR(5)*s**3
END SUBROUTINE FIELD

SUBROUTINE FUNC(NDIM, U, ICP, PAR, IJAC, F, DFDU, DFDP)
  IMPLICIT NONE
  INTEGER, INTENT(IN) :: NDIM, ICP(*), IJAC
  DOUBLE PRECISION, INTENT(IN) :: U(NDIM), PAR(*)
  DOUBLE PRECISION, INTENT(OUT) :: F(NDIM)
  DOUBLE PRECISION, INTENT(INOUT) :: DFDU(NDIM,NDIM), DFDP(NDIM,*)
  CALL FIELD(U, PAR, F)
  F = PAR(6)*F
END SUBROUTINE FUNC

SUBROUTINE STPNT(NDIM, U, PAR, T)
  ! Near-Hopf orbit at v = 0.4409 from first-harmonic averaging
  ! (Thomsen & Fidlin 2003): amplitude a = 2 sqrt((k1-2beta-3k3v^2)/(3k3)).
  ! The equilibrium run overrides v and U in its constants file.
  IMPLICIT NONE
  INTEGER, INTENT(IN) :: NDIM
  DOUBLE PRECISION, INTENT(INOUT) :: U(NDIM), PAR(*)
  DOUBLE PRECISION, INTENT(IN) :: T
  DOUBLE PRECISION, PARAMETER :: PI = 3.14159265358979323846D0
  DOUBLE PRECISION beta, mus, mum, vm, v, a
  beta = 0.05D0
  mus = 0.4D0
  mum = 0.25D0
  vm = 0.5D0
  v = 0.4409D0
  PAR(1) = v
  PAR(2) = beta
  PAR(3) = mus
  PAR(4) = 3*(mus - mum)/(2*vm)
  PAR(5) = (mus - mum)/(2*vm**3)
  PAR(6) = 2*PI
  a = 2*SQRT(MAX(0D0, (PAR(4) - 2*beta - 3*PAR(5)*v**2)/(3*PAR(5))))
  U(1) = PAR(3) - PAR(4)*v + PAR(5)*v**3 + a*SIN(2*PI*T)
  U(2) = a*COS(2*PI*T)
END SUBROUTINE STPNT

SUBROUTINE BCND(NDIM, PAR, ICP, NBC, U0, U1, FB, IJAC, DBC)
  ! Periodicity, and y'(0) = 0 (the phase: the orbit starts at max y).
  IMPLICIT NONE
  INTEGER, INTENT(IN) :: NDIM, ICP(*), NBC, IJAC
  DOUBLE PRECISION, INTENT(IN) :: PAR(*), U0(NDIM), U1(NDIM)
  DOUBLE PRECISION, INTENT(OUT) :: FB(NBC)
  DOUBLE PRECISION, INTENT(INOUT) :: DBC(NBC,*)
  DOUBLE PRECISION F(2)
  CALL FIELD(U0, PAR, F)
  FB(1) = U0(1) - U1(1)
  FB(2) = U0(2) - U1(2)
  FB(3) = F(2)
END SUBROUTINE BCND

SUBROUTINE PVLS(NDIM, U, PAR)
  IMPLICIT NONE
  INTEGER, INTENT(IN) :: NDIM
  DOUBLE PRECISION, INTENT(IN) :: U(NDIM)
  DOUBLE PRECISION, INTENT(INOUT) :: PAR(*)
  DOUBLE PRECISION, EXTERNAL :: GETP
  PAR(9) = GETP('BV0', 2, U) - PAR(1)
  PAR(7) = PAR(1) - ANINT(PAR(1)*1D5)/1D5
  PAR(8) = PAR(6) - ANINT(PAR(6)*1D5)/1D5
END SUBROUTINE PVLS

SUBROUTINE ICND
END SUBROUTINE ICND

SUBROUTINE FOPT
END SUBROUTINE FOPT
