!> STAT_NON_LINE/RECH_LINEAIRE: Code_Aster's line search on the residual (U4.51.03 §
!> RECH_LINEAIRE, R5.03.01 "recherche linéaire"), the rules of the step only; the Newton
!> step (contact_newton) evaluates the function and moves the iterate.
!>
!> Along the Newton correction p, f(rho) = p . (f_int - f_ext)(u + rho p), the derivative of
!> the energy along p (f(0) < 0 for a descent direction); the search looks for a zero of f.
!> It starts at rho = 1 and stops as soon as |f(rho)| < RESI_LINE_RELA |f(0)|, after at most
!> ITER_LINE_MAXI + 1 evaluations; it keeps the rho of the smallest |f| met (taken when
!> the criterion is never met). Each new rho is kept in [RHO_MIN, RHO_MAX] and out of
!> (-RHO_EXCL, RHO_EXCL).
!>   CORDE : the secant through the last two points, (f rho_m - f_m rho) / (f - f_m); equal
!>           values: RHO_MAX if f still points forward, else RHO_MIN.
!>   MIXTE : bracketing first (rho tripled while f keeps the sign of f(0)), then the secant
!>           inside the bracket, bisection when the secant is not pertinent (|f| did not
!>           decrease, or the slope is too flat), projected back into the bracket.
!> Code_Aster's defaults (c_rech_lineaire.py): CORDE, RESI_LINE_RELA 0.1, ITER_LINE_MAXI 3,
!> RHO_MIN 1e-2, RHO_MAX 10, RHO_EXCL 9e-3. ITER_LINE_MAXI = 0 switches the search off.
module residual_line_search
    use kinds, only: dp, i4
    implicit none
    private

    !> RECH_LINEAIRE as read (enabled: the keyword is given and ITER_LINE_MAXI > 0).
    type, public :: line_search_options_t
        logical :: enabled = .false.
        logical :: mixte = .false.                   !< METHODE = 'MIXTE' (else 'CORDE')
        real(dp) :: resi_line_rela = 1.0e-1_dp
        integer(i4) :: iter_line_maxi = 3
        real(dp) :: rho_min = 1.0e-2_dp, rho_max = 1.0e1_dp, rho_excl = 0.9e-2_dp
    end type line_search_options_t

    !> The search under way: the next rho to evaluate is `sens * rho`.
    type, public :: secant_search_t
        real(dp) :: rho = 1.0_dp, rho_prev = 0.0_dp
        real(dp) :: f0 = 0.0_dp, f_prev = 0.0_dp
        real(dp) :: rho_best = 1.0_dp, f_best = huge(1.0_dp)
        real(dp) :: sens = 1.0_dp
        real(dp) :: rho_neg = 0.0_dp, rho_pos = 0.0_dp
        logical :: bracketed = .false.
        logical :: converged = .false.
        integer(i4) :: evaluations = 0
    end type secant_search_t

    public :: search_start, search_next, search_trial, search_result

contains

    !> Starts a search from f(0) = f0: first trial rho = 1.
    pure subroutine search_start(ss, opts, f0)
        type(secant_search_t), intent(out) :: ss
        type(line_search_options_t), intent(in) :: opts
        real(dp), intent(in) :: f0
        ss%f0 = f0
        ss%f_prev = f0
        ss%rho = 1.0_dp
        ss%rho_prev = 0.0_dp
        ss%sens = 1.0_dp
        if (opts%mixte .and. f0 > 0.0_dp) ss%sens = -1.0_dp
    end subroutine search_start

    !> The rho to evaluate next.
    pure real(dp) function search_trial(ss)
        type(secant_search_t), intent(in) :: ss
        search_trial = ss%sens * ss%rho
    end function search_trial

    !> The rho the search ends on: the best one met.
    pure real(dp) function search_result(ss)
        type(secant_search_t), intent(in) :: ss
        search_result = ss%sens * ss%rho_best
    end function search_result

    !> Takes f at search_trial(ss); done: stop (converged, or ITER_LINE_MAXI + 1 evaluations,
    !> or MIXTE found no better point), then search_result(ss) is the step.
    pure subroutine search_next(ss, opts, f, done)
        type(secant_search_t), intent(inout) :: ss
        type(line_search_options_t), intent(in) :: opts
        real(dp), intent(in) :: f
        logical, intent(out) :: done
        real(dp) :: rho_here, slope, intercept
        ss%evaluations = ss%evaluations + 1
        done = .false.
        if (abs(f) <= ss%f_best) then
            ss%rho_best = ss%rho
            ss%f_best = abs(f)
            if (abs(f) < opts%resi_line_rela * abs(ss%f0)) then
                ss%converged = .true.
                done = .true.
                return
            end if
        end if
        if (ss%evaluations > opts%iter_line_maxi) then
            done = .true.
            return
        end if
        rho_here = ss%rho
        if (.not. opts%mixte) then
            if (abs(f - ss%f_prev) > tiny(1.0_dp)) then
                ss%rho = limited((f * ss%rho_prev - ss%f_prev * ss%rho) / (f - ss%f_prev), opts)
            else if (f * (ss%rho - ss%rho_prev) * (f - ss%f_prev) <= 0.0_dp) then
                ss%rho = opts%rho_max
            else
                ss%rho = opts%rho_min
            end if
        else
            if ((f > 0.0_dp) .eqv. (ss%f0 > 0.0_dp)) then
                ss%rho_neg = ss%rho
            else
                ss%rho_pos = ss%rho
                ss%bracketed = .true.
            end if
            if (.not. ss%bracketed) then
                ss%rho = 3.0_dp * rho_here                      ! widen: f kept its sign
            else if (abs(f) >= abs(ss%f_prev)) then
                ss%rho = 0.5_dp * (ss%rho_neg + ss%rho_pos)     ! secant not pertinent
            else if (abs(ss%rho - ss%rho_prev) > tiny(1.0_dp)) then
                slope = (f - ss%f_prev) / (ss%rho - ss%rho_prev)
                intercept = ss%f_prev - slope * ss%rho_prev
                if (abs(slope) <= abs(ss%f_prev) / (ss%rho_pos + ss%rho_prev)) then
                    ss%rho = 0.5_dp * (ss%rho_neg + ss%rho_pos)
                else
                    ss%rho = -intercept / slope
                end if
            else
                done = .true.
                return
            end if
            if (ss%rho < ss%rho_neg) then
                if (.not. ss%bracketed) then
                    done = .true.
                    return
                end if
                ss%rho = 0.5_dp * (ss%rho_neg + ss%rho_pos)
            end if
            if (ss%bracketed .and. ss%rho > ss%rho_pos) ss%rho = 0.5_dp * (ss%rho_neg + ss%rho_pos)
            ss%rho = limited(ss%rho, opts)
        end if
        ss%rho_prev = rho_here
        ss%f_prev = f
    end subroutine search_next

    !> rho kept in [RHO_MIN, RHO_MAX] and out of (-RHO_EXCL, RHO_EXCL).
    pure real(dp) function limited(rho, opts)
        real(dp), intent(in) :: rho
        type(line_search_options_t), intent(in) :: opts
        limited = min(max(rho, opts%rho_min), opts%rho_max)
        if (limited < 0.0_dp .and. limited >= -opts%rho_excl) limited = -opts%rho_excl
        if (limited >= 0.0_dp .and. limited <= opts%rho_excl) limited = opts%rho_excl
    end function limited

end module residual_line_search
