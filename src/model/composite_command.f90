!> DEFI_COMPOSITE (U4.42.03): a laminate for DKT plates, its layers from the bottom face up
!> (COUCHE: EPAIS, MATER of ELAS_ORTH, ORIENTATION in degrees from the user frame's x
!> axis). The result is a material whose behaviour ELAS_COQMU keeps, per layer, the
!> thickness, orientation and elastic constants (E_L, E_T, NU_LT, G_LT; G_LN, G_TN with
!> Code_Aster's defaults G_LT and 10^6 G_LT; ALPHA_L, ALPHA_T, RHO when given):
!> model_plate_section integrates them for each cell. Code_Aster's op0056 accepts only
!> ELAS_ORTH layers (MODELISA8_71), as here. IMPRESSION is accepted (no listing written).
module composite_command
    use kinds, only: dp, i4
    use status, only: status_t, STATUS_MODEL_ERROR
    use strings, only: to_text, string_t, real_e13
    use number_limits, only: MIN_MODULUS, MAX_MODULUS, MAX_POISSON
    use deck_concept, only: concept_t, concept_display_name
    use deck_command, only: command_t, keyword_set_t
    use run_context, only: run_context_t
    use model_material, only: material_t, behaviour_t, material_value_t, add_behaviour, &
        has_behaviour, behaviour_number, VALUE_NUMBERS, VALUE_TEXTS
    use material_concept, only: material_concept_t
    implicit none
    private

    public :: run_defi_composite

    !> The per-layer values kept (module header).
    character(len=*), parameter :: KEYS(11) = [character(len=11) :: 'EPAIS', 'ORIENTATION', &
        'E_L', 'E_T', 'NU_LT', 'G_LT', 'G_LN', 'G_TN', 'ALPHA_L', 'ALPHA_T', 'RHO']

contains

    !> DEFI_COMPOSITE (module header).
    !>  result : out, a material_concept_t with the behaviour ELAS_COQMU
    !>  st     : located at COUCHE/MATER: a material without ELAS_ORTH (or whose ELAS_ORTH
    !>           gives functions)
    subroutine run_defi_composite(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        type(material_concept_t), allocatable :: mc
        type(keyword_set_t) :: occ
        type(behaviour_t) :: b
        real(dp) :: values(size(KEYS))
        real(dp), allocatable :: table(:, :)
        type(string_t), allocatable :: names(:)
        class(concept_t), pointer :: p
        integer(i4) :: n, i, k
        n = cmd%count('COUCHE')
        allocate (table(size(KEYS), n), names(n))
        do i = 1, n
            occ = cmd%occurrence('COUCHE', i)
            call occ%get_real('EPAIS', values(1), st)
            if (st%failed()) return
            values(2) = 0.0_dp
            if (occ%has('ORIENTATION')) call occ%get_real('ORIENTATION', values(2), st)
            if (st%ok()) call occ%get_concept('MATER', p, st)
            if (st%failed()) return
            select type (p)
            type is (material_concept_t)
                call layer_values(occ, p%material, values(3:), st)
                if (st%failed()) return
                names(i)%s = concept_display_name(p)
            class default
                call occ%error_at('MATER', 'expected a material (mater), got ' // &
                    p%type_name(), st)
                return
            end select
            table(:, i) = values
        end do
        b%name = 'ELAS_COQMU'
        allocate (b%values(size(KEYS) + 1))
        do k = 1, size(KEYS)
            b%values(k)%key = trim(KEYS(k))
            b%values(k)%kind = VALUE_NUMBERS
            b%values(k)%numbers = table(k, :)
        end do
        b%values(size(KEYS) + 1)%key = 'MATER'
        b%values(size(KEYS) + 1)%kind = VALUE_TEXTS
        b%values(size(KEYS) + 1)%texts = names
        allocate (mc)
        call add_behaviour(mc%material, b)
        call ctx%write_mess('    DEFI_COMPOSITE: ' // to_text(n) // ' layer(s), ' // &
            to_text(sum(table(1, :))) // ' thick')
        call move_alloc(mc, result)
    end subroutine run_defi_composite

    ! E_L ... RHO of a layer's ELAS_ORTH (values(1:9) for KEYS(3:11)).
    subroutine layer_values(occ, mat, values, st)
        type(keyword_set_t), intent(in) :: occ
        type(material_t), intent(in) :: mat
        real(dp), intent(out) :: values(:)
        type(status_t), intent(out) :: st
        logical :: found
        integer :: k
        if (.not. has_behaviour(mat, 'ELAS_ORTH')) then
            call occ%error_at('MATER', 'a layer of DEFI_COMPOSITE takes a material with ' // &
                'ELAS_ORTH (Code_Aster MODELISA8_71)', st, code=STATUS_MODEL_ERROR)
            return
        end if
        do k = 3, size(KEYS)
            call behaviour_number(mat, 'ELAS_ORTH', trim(KEYS(k)), values(k - 2), found)
            if (found) cycle
            select case (KEYS(k))
            case ('E_L', 'E_T', 'NU_LT', 'G_LT')
                call occ%error_at('MATER', 'the layer''s ELAS_ORTH gives no number ' // &
                    trim(KEYS(k)), st, code=STATUS_MODEL_ERROR)
                return
            case ('G_LN')
                values(k - 2) = values(4)                 ! G_LT
            case ('G_TN')
                values(k - 2) = 1.0e6_dp * values(4)      ! op0056's default
            case default
                values(k - 2) = 0.0_dp
            end select
        end do
        ! the moduli (E_L, E_T, G_LT, G_LN, G_TN) bounded as ELAS's E and NU_LT as ELAS_ORTH's
        ! (number_limits): the layer's stiffness is formed from their ratios
        if (any(values([1, 2, 4, 5, 6]) < MIN_MODULUS .or. &
                values([1, 2, 4, 5, 6]) > MAX_MODULUS) .or. abs(values(3)) > MAX_POISSON) then
            call occ%error_at('MATER', 'the layer''s ELAS_ORTH: E_L, E_T, G_LT, G_LN and ' // &
                'G_TN must lie in [' // real_e13(MIN_MODULUS) // ', ' // &
                real_e13(MAX_MODULUS) // '] and |NU_LT| <= ' // real_e13(MAX_POISSON) // &
                ' (E_L ' // real_e13(values(1)) // ', E_T ' // real_e13(values(2)) // &
                ', NU_LT ' // real_e13(values(3)) // ', G_LT ' // real_e13(values(4)) // ')', &
                st, code=STATUS_MODEL_ERROR)
            return
        end if
    end subroutine layer_values

end module composite_command
