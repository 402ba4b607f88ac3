!> The catalog of DEFI_MATERIAU (Code_Aster U4.43.01): every behaviour keyword of
!> Code_Aster's catalog is accepted as data (doc/deck-language.md, "Materials as data").
!> ELAS and DIS_CONTACT, which parasol's elements use, are described here by hand with the
!> ranges parasol checks (issue 13); the other behaviours come from the table that
!> tools/aster_material_table.py writes from Code_Aster's catalog (catalog_material_data),
!> decoded here into keywords and rules.
!> Part of THE command catalog (deck_catalog_data gathers the parts).
module catalog_materials
    use kinds, only: dp
    use deck_catalog, only: catalog_t, MANY, RULE_EXCLUS, RULE_UN_PARMI, RULE_AU_MOINS_UN, &
        RULE_PRESENT_PRESENT, RULE_PRESENT_ABSENT, RULE_ENSEMBLE
    use number_limits, only: MAX_LENGTH, MAX_MODULUS, MIN_MODULUS
    use catalog_material_data, only: material_table, MATERIAL_TABLE_LENGTH
    implicit none
    private
    public :: describe_materials

contains

    subroutine describe_materials(c)
        type(catalog_t), intent(inout) :: c
        call c%command('DEFI_MATERIAU', 'mater', reentrant='f:MATER')
        call c%key('MATER', 'mater')        ! reuse: the material completed (reentrant 'f')
        call c%key('INFO', 'I', def='1', into='1 2')
        call c%key('COMP_THM', 'TXM', into='LIQU_SATU LIQU_GAZ GAZ LIQU_GAZ_ATM ' // &
                   'LIQU_VAPE_GAZ LIQU_AD_GAZ LIQU_VAPE LIQU_AD_GAZ_VAPE')
        call describe_elas(c)
        call describe_dis_contact(c)
        call decode_table(c)
        call describe_composite(c)
    end subroutine describe_materials

    !> DEFI_COMPOSITE (U4.42.03): the layers of a laminate, from the bottom face up.
    subroutine describe_composite(c)
        type(catalog_t), intent(inout) :: c
        call c%command('DEFI_COMPOSITE', 'mater')
        call c%fact('COUCHE', max=MANY, req=.true.)
        call c%key('EPAIS', 'R', req=.true., vmin=0.0_dp, vmax=MAX_LENGTH)
        call c%key('MATER', 'mater', req=.true.)
        call c%key('ORIENTATION', 'R', def='0.0', vmin=-90.0_dp, vmax=90.0_dp)
        call c%end_fact()
        call c%fact('IMPRESSION')
        call c%key('UNITE', 'I', def='8')
        call c%end_fact()
    end subroutine describe_composite

    !> ELAS (Code_Aster's keywords and rules): E and NU, or K and MU, or CELE_P and CELE_S
    !> with RHO; the others are data. Values the elements form products from are bounded.
    subroutine describe_elas(c)
        type(catalog_t), intent(inout) :: c
        call c%fact('ELAS')
        call c%key('E', 'R', vmin=0.0_dp, vmax=MAX_MODULUS, vtiny=MIN_MODULUS)  ! E > 0: handler
        call c%key('NU', 'R', vmin=-1.0_dp, vmax=0.5_dp)
        call c%key('K', 'R', vmin=0.0_dp, vmax=MAX_MODULUS, vtiny=MIN_MODULUS)
        call c%key('MU', 'R', vmin=0.0_dp, vmax=MAX_MODULUS, vtiny=MIN_MODULUS)
        call c%key('CELE_P', 'R', vmin=0.0_dp, vmax=MAX_MODULUS, vtiny=MIN_MODULUS)
        call c%key('CELE_S', 'R', vmin=0.0_dp, vmax=MAX_MODULUS, vtiny=MIN_MODULUS)
        call c%key('RHO', 'R', vmin=-MAX_MODULUS, vmax=MAX_MODULUS)
        call c%key('ALPHA', 'R', vmin=-MAX_MODULUS, vmax=MAX_MODULUS)
        call c%key('AMOR_ALPHA', 'R')
        call c%key('AMOR_BETA', 'R')
        call c%key('AMOR_HYST', 'R')
        call c%key('K_DESSIC', 'R', def='0.0')
        call c%key('B_ENDOGE', 'R', def='0.0')
        call c%key('LONG_CARA', 'R', vmin=0.0_dp)
        call c%key('COEF_AMOR', 'R', def='1.0')
        call c%rule(RULE_UN_PARMI, 'E K CELE_P')
        call c%rule(RULE_ENSEMBLE, 'E NU')
        call c%rule(RULE_ENSEMBLE, 'K MU')
        call c%rule(RULE_ENSEMBLE, 'CELE_P CELE_S')
        call c%rule(RULE_PRESENT_PRESENT, 'CELE_P RHO')
        call c%end_fact()
    end subroutine describe_elas

    !> DIS_CONTACT (DIS_CHOC and DIS_CONTACT springs): Code_Aster's keywords and rules;
    !> parasol's defaults for the values it uses (0), and bounds on lengths and stiffnesses.
    subroutine describe_dis_contact(c)
        type(catalog_t), intent(inout) :: c
        call c%fact('DIS_CONTACT')
        call c%key('RIGI_NOR', 'R', vmin=0.0_dp, vmax=MAX_MODULUS, vtiny=MIN_MODULUS)
        call c%key('RIGI_TAN', 'R', def='0.0', vmin=0.0_dp, vmax=MAX_MODULUS, &
                   vtiny=MIN_MODULUS)
        call c%key('AMOR_NOR', 'R', def='0.0', vmin=0.0_dp, vmax=MAX_MODULUS)
        call c%key('AMOR_TAN', 'R', def='0.0', vmin=0.0_dp, vmax=MAX_MODULUS)
        call c%key('KP', 'R', def='0.0')
        call c%key('KT', 'R', def='0.0')
        call c%key('KT1', 'R', def='0.0')
        call c%key('KT2', 'R', def='0.0')
        call c%key('COULOMB', 'R', def='0.0', vmin=0.0_dp)
        call c%key('DIST_1', 'R', def='0.0', vmin=-MAX_LENGTH, vmax=MAX_LENGTH)
        call c%key('DIST_2', 'R', def='0.0', vmin=-MAX_LENGTH, vmax=MAX_LENGTH)
        call c%key('JEU', 'R', def='0.0', vmin=-MAX_LENGTH, vmax=MAX_LENGTH)
        call c%key('INST_COMP_INIT', 'R', min=2, max=2)
        call c%key('CONTACT', 'TXM', def='1D', into='1D COIN_2D')
        call c%key('PRECISION', 'R', min=3, max=3)
        call c%rule(RULE_AU_MOINS_UN, 'RIGI_NOR RIGI_TAN AMOR_NOR AMOR_TAN KP KT KT1 KT2 ' // &
                    'COULOMB DIST_1 DIST_2 JEU INST_COMP_INIT CONTACT PRECISION')   ! NON_VIDE
        call c%rule(RULE_PRESENT_ABSENT, 'DIST_2 JEU')
        call c%end_fact()
    end subroutine describe_dis_contact

    !> Decodes catalog_material_data's tokens (tools/aster_material_table.py describes
    !> them) into factor keywords, keywords and rules.
    subroutine decode_table(c)
        type(catalog_t), intent(inout) :: c
        character(len=MATERIAL_TABLE_LENGTH) :: text
        integer :: i, j
        call material_table(text)
        i = 1
        do while (i <= MATERIAL_TABLE_LENGTH)
            if (text(i:i) == ' ') then
                i = i + 1
                cycle
            end if
            j = index(text(i:) // ' ', ' ') + i - 2
            select case (text(i:i))
            case ('@')
                call c%end_fact()
                call c%fact(text(i + 1:j))
            case ('%')
                call decode_rule(c, text(i + 1:j))
            case default
                call decode_keyword(c, text(i:j))
            end select
            i = j + 1
        end do
        call c%end_fact()
    end subroutine decode_table

    ! RULE:A,B,C
    subroutine decode_rule(c, token)
        type(catalog_t), intent(inout) :: c
        character(len=*), intent(in) :: token
        character(len=len(token)) :: names
        integer :: colon, kind, k
        colon = index(token, ':')
        select case (token(1:colon - 1))
        case ('EXCLUS')
            kind = RULE_EXCLUS
        case ('UN_PARMI')
            kind = RULE_UN_PARMI
        case ('AU_MOINS_UN')
            kind = RULE_AU_MOINS_UN
        case ('PRESENT_PRESENT')
            kind = RULE_PRESENT_PRESENT
        case ('PRESENT_ABSENT')
            kind = RULE_PRESENT_ABSENT
        case ('ENSEMBLE')
            kind = RULE_ENSEMBLE
        case default
            return                          ! AU_PLUS_UN ...: not a parasol rule
        end select
        names = token(colon + 1:)
        do k = 1, len(names)
            if (names(k:k) == ',') names(k:k) = ' '
        end do
        call c%rule(kind, trim(names))
    end subroutine decode_rule

    ! KEY:TYPES[!][*N][#N][=DEF][{A|B}][<LO,HI>]
    subroutine decode_keyword(c, token)
        type(catalog_t), intent(inout) :: c
        character(len=*), intent(in) :: token
        character(len=:), allocatable :: name, types, default, into
        integer :: colon, p, q, max_values, min_values
        logical :: required, has_lo, has_hi
        real(dp) :: lo, hi
        colon = index(token, ':')
        name = token(1:colon - 1)
        p = colon + 1
        q = p
        do while (q <= len(token))
            if (index('RITFONBC', token(q:q)) == 0) exit
            q = q + 1
        end do
        types = type_names(token(p:q - 1))
        p = q
        required = .false.
        max_values = 1
        min_values = 1
        default = ''
        into = ''
        has_lo = .false.
        has_hi = .false.
        lo = 0.0_dp
        hi = 0.0_dp
        do while (p <= len(token))
            select case (token(p:p))
            case ('!')
                required = .true.
                p = p + 1
            case ('*', '#')
                q = p + 1
                do while (q <= len(token))
                    if (index('0123456789', token(q:q)) == 0) exit
                    q = q + 1
                end do
                if (token(p:p) == '*') then
                    read (token(p + 1:q - 1), *) max_values
                    if (max_values == 0) max_values = MANY
                else
                    read (token(p + 1:q - 1), *) min_values
                end if
                p = q
            case ('=')
                q = scan(token(p + 1:), '{<') + p
                if (q == p) q = len(token) + 1
                default = slashes_to_blanks(token(p + 1:q - 1))
                p = q
            case ('{')
                q = index(token(p:), '}') + p - 1
                into = slashes_to_blanks(bars_to_blanks(token(p + 1:q - 1)))
                p = q + 1
            case ('<')
                q = index(token(p:), '>') + p - 1
                call decode_range(token(p + 1:q - 1), has_lo, lo, has_hi, hi)
                p = q + 1
            case default
                p = p + 1
            end select
        end do
        call add_keyword(c, name, types, required, min_values, max_values, default, into, &
                         has_lo, lo, has_hi, hi)
    end subroutine decode_keyword

    subroutine add_keyword(c, name, types, required, min_values, max_values, default, into, &
                           has_lo, lo, has_hi, hi)
        type(catalog_t), intent(inout) :: c
        character(len=*), intent(in) :: name, types, default, into
        logical, intent(in) :: required, has_lo, has_hi
        integer, intent(in) :: min_values, max_values
        real(dp), intent(in) :: lo, hi
        if (has_lo .and. has_hi) then
            call c%key(name, types, min=min_values, max=max_values, req=required, &
                       def=default, into=into, vmin=lo, vmax=hi)
        else if (has_lo) then
            call c%key(name, types, min=min_values, max=max_values, req=required, &
                       def=default, into=into, vmin=lo)
        else if (has_hi) then
            call c%key(name, types, min=min_values, max=max_values, req=required, &
                       def=default, into=into, vmax=hi)
        else
            call c%key(name, types, min=min_values, max=max_values, req=required, &
                       def=default, into=into)
        end if
    end subroutine add_keyword

    ! 'LO,HI', either side possibly empty
    subroutine decode_range(text, has_lo, lo, has_hi, hi)
        character(len=*), intent(in) :: text
        logical, intent(out) :: has_lo, has_hi
        real(dp), intent(out) :: lo, hi
        integer :: comma
        comma = index(text, ',')
        has_lo = comma > 1
        has_hi = comma < len(text)
        lo = 0.0_dp
        hi = 0.0_dp
        if (has_lo) read (text(1:comma - 1), *) lo
        if (has_hi) read (text(comma + 1:), *) hi
    end subroutine decode_range

    ! Type letters -> catalog types: R real, I integer, T text, F fonction, O formule,
    ! N nappe, B table; C complex: the deck language has no complex numbers, ANY.
    function type_names(letters) result(types)
        character(len=*), intent(in) :: letters
        character(len=:), allocatable :: types
        integer :: k
        character(len=:), allocatable :: one
        types = ''
        do k = 1, len(letters)
            select case (letters(k:k))
            case ('R')
                one = 'R'
            case ('I')
                one = 'I'
            case ('T')
                one = 'TXM'
            case ('F')
                one = 'fonction'
            case ('O')
                one = 'formule'
            case ('N')
                one = 'nappe'
            case ('B')
                one = 'table'
            case default
                types = 'ANY'
                return
            end select
            if (len(types) > 0) types = types // '|'
            types = types // one
        end do
    end function type_names

    pure function bars_to_blanks(text) result(out)
        character(len=*), intent(in) :: text
        character(len=len(text)) :: out
        integer :: k
        out = text
        do k = 1, len(out)
            if (out(k:k) == '|') out(k:k) = ' '
        end do
    end function bars_to_blanks

    pure function slashes_to_blanks(text) result(out)
        character(len=*), intent(in) :: text
        character(len=len(text)) :: out
        integer :: k
        out = text
        do k = 1, len(out)
            if (out(k:k) == '/') out(k:k) = ' '
        end do
    end function slashes_to_blanks

end module catalog_materials
