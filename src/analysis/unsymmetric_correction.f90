!> Solving with a stiffness that is not symmetric (discretes with SYME='NON', Code_Aster
!> U4.42.01 §5) through the symmetric factor of the analysis. The assembled matrix holds the
!> symmetric part S of K (assembly_system); the skew part, N on the m equations the
!> unsymmetric discretes act on (assembly_unsymmetric), is of rank at most m. On the free
!> equations K = S + P N P^T, P^T = the rows of T (the elimination, scatter_free) at those
!> equations, P = T^T e_j (gather_free), and the Sherman-Morrison-Woodbury identity
!>     K^-1 b = y - Z C^-1 N P^T y,   y = S^-1 b,   Z = S^-1 P,   C = I + N P^T Z
!> (Golub & Van Loan, Matrix Computations, 4th ed., §2.1.4; C factored by dense_lu) solves with K exactly, at the
!> cost of m solves with the factor of S once and a dense m x m LU. det K = det S det C:
!> K is singular exactly when C is, which the pivots of C's LU tell (NPREC as for S).
!> Code_Aster factors the unsymmetric K itself (MUMPS with SYM=0); the answers agree to
!> round-off, the cost grows with m (at most MAX_SKEW_EQUATIONS, MAX_SKEW_TERMS).
!> Every operator here is linear, so it works in the solver's hat coordinates
!> (two_level_solver: rigid modes of spring-held bodies kept apart) as the caller does.
module unsymmetric_correction
    use kinds, only: dp, i4, i8
    use status, only: status_t, set_error, STATUS_MODEL_ERROR, STATUS_SINGULAR
    use strings, only: to_text, real_short
    use sparse_matrix, only: sym_matrix_t
    use direct_solver, only: direct_solver_t, solver_options_t, effective_nprec
    use two_level_solver, only: from_hat
    use dense_lu, only: lu_factor, lu_solve
    use model_dof_numbering, only: describe_equation
    use assembly_system, only: structure_t, assembly_map_t, gather_free, scatter_free
    use assembly_unsymmetric, only: skew_stiffness
    use analysis_solver, only: solve_held, held_t
    use analysis_log, only: analysis_log_t, log_add
    implicit none
    private

    !> At most this many equations under the skew part: C is dense (m^2 reals, m^3/3 flops).
    integer(i4), parameter, public :: MAX_SKEW_EQUATIONS = 2000
    !> At most this many reals in Z (m solves of n_free reals): 2 GiB.
    integer(i8), parameter, public :: MAX_SKEW_TERMS = 268435456_i8

    !> The correction, ready to apply (skew_prepare).
    type, public :: skew_correction_t
        integer(i4) :: m = 0                      !< 0: K is symmetric, nothing to do
        integer(i4), allocatable :: eqs(:)        !< (m) original equations under N
        real(dp), allocatable :: skew(:, :)       !< (m, m) N
        real(dp), allocatable :: zhat(:, :)       !< (n_free, m) S^-1 P, hat coordinates
        real(dp), allocatable :: lu(:, :)         !< (m, m) LU of C (dense_lu)
        integer(i4), allocatable :: pivots(:)     !< (m) its row interchanges
        real(dp) :: digits_lost = 0.0_dp          !< worst pivot of C against max |C|
    end type skew_correction_t

    public :: skew_prepare, skew_correct

contains

    !> Builds the correction for the factored symmetric part (matrix, solver, held: as
    !> solve_held takes them). Nothing (m = 0) when no discrete is unsymmetric.
    !>  t   : in, the instant (messages)
    !>  st  : out, STATUS_MODEL_ERROR beyond MAX_SKEW_EQUATIONS / MAX_SKEW_TERMS;
    !>        STATUS_SINGULAR when C is (K singular), naming the node and component;
    !>        the solver's failures
    subroutine skew_prepare(s, map, matrix, solver, held, options, t, log, corr, st)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        type(sym_matrix_t), intent(in) :: matrix
        class(direct_solver_t), intent(inout) :: solver
        type(held_t), intent(inout) :: held
        type(solver_options_t), intent(in) :: options
        real(dp), intent(in) :: t
        type(analysis_log_t), intent(inout) :: log
        type(skew_correction_t), intent(out) :: corr
        type(status_t), intent(out) :: st
        integer(i4), allocatable :: eqs(:), keep(:)
        logical, allocatable :: kept(:)
        real(dp), allocatable :: skew(:, :), e(:), p(:), z(:), v(:), g(:, :)
        integer(i4) :: j, m, n_eq, worst, zero_at
        real(dp) :: scale, digits
        call skew_stiffness(s, map, MAX_SKEW_EQUATIONS, eqs, skew, st)
        if (st%failed() .or. size(eqs) == 0) return
        n_eq = s%dofs%n_equations
        if (.not. allocated(skew)) then
            call refuse(size(eqs, kind=i4), 'at least ')
            return
        end if
        allocate (e(n_eq), p(map%n_free), kept(size(eqs)))
        ! a slave whose relation holds on imposed equations only carries no unknown either:
        ! P e_j = 0, its row and column of N drop out exactly
        e = 0.0_dp
        do j = 1, size(eqs)
            e(eqs(j)) = 1.0_dp
            call gather_free(map, e, p)
            e(eqs(j)) = 0.0_dp
            kept(j) = any(abs(p) > 0.0_dp)
        end do
        keep = pack([(j, j = 1, size(eqs, kind=i4))], kept)
        m = size(keep)
        if (m == 0) return
        if (int(m, i8) * map%n_free > MAX_SKEW_TERMS) then
            call refuse(m, '')
            return
        end if
        corr%m = m
        corr%eqs = eqs(keep)
        corr%skew = skew(keep, keep)
        allocate (corr%zhat(map%n_free, m), z(map%n_free), v(n_eq), g(m, m))
        do j = 1, m
            e(corr%eqs(j)) = 1.0_dp
            call gather_free(map, e, p)
            e(corr%eqs(j)) = 0.0_dp
            call solve_held(s, map, matrix, solver, held, p, t, log, st)
            if (st%failed()) return
            corr%zhat(:, j) = p
            call from_hat(solver, p, z)
            call scatter_free(map, z, v)
            g(:, j) = v(corr%eqs)
        end do
        ! C = I + N P^T Z
        corr%lu = matmul(corr%skew, g)
        do j = 1, m
            corr%lu(j, j) = corr%lu(j, j) + 1.0_dp
        end do
        scale = maxval(abs(corr%lu))
        allocate (corr%pivots(m))
        call lu_factor(corr%lu, corr%pivots, zero_at)
        worst = 1
        digits = 0.0_dp
        do j = 1, m
            if (.not. abs(corr%lu(j, j)) > 0.0_dp) then
                worst = j
                digits = huge(1.0_dp)
                exit
            end if
            if (log10(scale / abs(corr%lu(j, j))) > digits) then
                digits = log10(scale / abs(corr%lu(j, j)))
                worst = j
            end if
        end do
        corr%digits_lost = digits
        if (zero_at /= 0 .or. digits > real(effective_nprec(options), dp)) then
            call set_error(st, STATUS_SINGULAR, 'singular matrix at ' // &
                describe_equation(s%dofs, s%mesh, corr%eqs(worst)) // ': with the ' // &
                'discretes of SYME=''NON'' the stiffness is singular (its correction ' // &
                'of the symmetric part lost ' // lost_text() // ', more than NPREC = ' // &
                to_text(effective_nprec(options)) // '); a support (DDL_IMPO) or a ' // &
                'stiffness is missing there, or the discrete''s matrix is singular')
            return
        end if
        call log_add(log, 'SYME=''NON'': ' // to_text(m) // ' free equation(s) under the ' // &
            'skew part of the discretes'' stiffness: the symmetric part is factored and ' // &
            'the solves corrected (rank ' // to_text(m) // ', ' // to_text(m) // &
            ' solve(s)); the correction lost ' // real_short(digits) // ' digits')
    contains
        ! the digits C's worst pivot lost, for the message
        function lost_text() result(text)
            character(len=:), allocatable :: text
            if (zero_at /= 0) then
                text = 'all digits (a zero pivot)'
            else
                text = real_short(digits) // ' digits'
            end if
        end function lost_text
        ! beyond MAX_SKEW_EQUATIONS / MAX_SKEW_TERMS: what the correction would need
        subroutine refuse(count, qualifier)
            integer(i4), intent(in) :: count
            character(len=*), intent(in) :: qualifier
            call set_error(st, STATUS_MODEL_ERROR, 'the discretes with SYME=''NON'' and a ' // &
                'matrix that is not symmetric act on ' // qualifier // to_text(count) // &
                ' free equations of ' // to_text(map%n_free) // ': parasol solves with ' // &
                'their skew part by a dense correction of the symmetric factor, limited to ' &
                // to_text(MAX_SKEW_EQUATIONS) // ' equations and ' // &
                to_text(MAX_SKEW_TERMS) // ' stored reals (equations x free equations); ' // &
                'give fewer such discretes, or symmetric matrices (SYME=''OUI'')')
        end subroutine refuse
    end subroutine skew_prepare

    !> rhat <- hat coordinates of K^-1 b, given rhat = those of S^-1 b (solve_held).
    subroutine skew_correct(map, solver, corr, rhat)
        type(assembly_map_t), intent(in) :: map
        class(direct_solver_t), intent(in) :: solver
        type(skew_correction_t), intent(in) :: corr
        real(dp), intent(inout) :: rhat(:)
        real(dp), allocatable :: x(:), v(:), w(:)
        integer(i4) :: n_eq
        if (corr%m == 0) return
        n_eq = size(map%free_eq, kind=i4)
        allocate (x(size(rhat)), v(n_eq))
        call from_hat(solver, rhat, x)
        call scatter_free(map, x, v)
        w = matmul(corr%skew, v(corr%eqs))
        call lu_solve(corr%lu, corr%pivots, w)
        rhat = rhat - matmul(corr%zhat, w)
    end subroutine skew_correct

end module unsymmetric_correction
